// Grades one assignment against its spec (grading_spec.h): runs the task
// tests (lightlab_task_tests, filtered per task) and the renders (lightlab
// render) as child processes with time limits, so a crash or an endless loop
// in student code fails that test and nothing else; compares the renders with
// the reference images; times the complexity probes. Tasks whose stub ran
// are "not implemented" and score 0.
#pragma once

#include <string>

#include "grading/grade_result.h"
#include "grading/grading_spec.h"

namespace ll::grading {

struct GraderOptions {
  std::string dataDir;    // data/ of the source tree (scenes, references)
  std::string buildDir;   // the build folder ("@build/" in specs)
  std::string lightlab;   // the lightlab program, for renders
  std::string taskTests;  // the lightlab_task_tests program
  std::string reportDir;  // images and scratch files go to <reportDir>/files
  unsigned seed = 1;      // passed to every render (--seed)
  int threads = 0;        // passed to every child (--threads; 0 = all cores)
  std::string onlyTask;   // grade only this task ID (empty: all)
  bool quiet = false;     // no progress bar
  double unitTimeout = 900.0;    // seconds per task's unit tests
  double renderTimeout = 600.0;  // seconds per render
};

GradeResult grade(const GradingSpec& spec, const GraderOptions& options);

}  // namespace ll::grading
