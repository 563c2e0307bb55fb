// Grades one assignment against its spec (grading_spec.h). Every piece of
// student code runs in a child process -- the task tests (lightlab_task_tests)
// and the renders (lightlab render) -- with time limits, capped output and,
// in the autograder, as an unprivileged user with resource limits; the
// grader itself loads no student code. Results come only from what the
// grader observes: the task tests' result channel (core/subprocess.h, a key
// student code never sees), exit statuses, and the files a render wrote,
// read after every process of the child is gone.
//
// Each task is graded on its own: while its tests run, every other task runs
// its reference (tasks/task_modes.h), so a stub or a bug elsewhere never
// costs it points. A test that exits, crashes or hangs fails alone; the rest
// of its group is run again. Tasks whose stub ran score 0; a task that uses
// the framework's own answer to itself fails that test with the reason.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/subprocess.h"
#include "grading/grade_result.h"
#include "grading/grading_spec.h"

namespace ll::grading {

struct GraderOptions {
  std::string dataDir;     // data/ of the source tree (scenes, references)
  std::string buildDir;    // the build folder ("@build/" in specs)
  std::string lightlab;    // the lightlab program, for renders
  std::string taskTests;   // the lightlab_task_tests program
  std::string reportDir;   // reports; images go to <reportDir>/files
  std::string sourceDir;   // the student's files (checked for forbidden names); "" = the spec's folder
  std::string workDir;     // where children run and write; "" = <reportDir>/files/work
  unsigned seed = 1;       // passed to every render (--seed)
  int threads = 0;         // passed to every child (--threads; 0 = all cores)
  std::string onlyTask;    // grade only this task ID (empty: all)
  bool quiet = false;      // no progress bar
  double budgetSeconds = 480.0;  // the whole grading: what has not run by then fails as "not run"
  double testTimeout = 30.0;     // one task test, from its start
  double groupTimeout = 120.0;   // one run of the task-test program
  double renderTimeout = 120.0;  // one render
  Sandbox sandbox;               // as whom student code runs (the autograder); default: as this user
  std::vector<std::string> childEnv;  // "NAME=value" for every child: module folders, LIGHTLAB_GRADING_SEED
  std::map<std::string, std::string> buildFailures;  // task ID -> compiler output: its module did not build
};

GradeResult grade(const GradingSpec& spec, const GraderOptions& options);

}  // namespace ll::grading
