// An assignment's grading spec: assignments/<dir>/grading.json lists the
// tasks (ID, title, points, the file and functions the student writes,
// "recursive" for a task that calls itself through the framework,
// "forbidden": names the task's file must not use, "uses": the other tasks
// its tests run, by their references, "optional": true for extra credit,
// whose points are not part of the maximum) and, per task, the tests
// that grade it:
//
//   {"kind": "unit"}                           the task's tests in lightlab_task_tests: every case
//                                              whose suite names the task (A2_4_*, A6/A6_1_Furnace.*),
//                                              each a test; optional "filter" narrows them
//                                              (a GoogleTest filter)
//   {"kind": "image", "reference": "a2/sphere_point_light.hdr"}
//        a render against a reference image of data/references/<dir>/references.json:
//        its tolerances plus a per-pixel one, or, for a Monte Carlo entry (with a
//        variance image), the per-pixel Z-test of metrics/pixel_ztest.h
//   {"kind": "complexity", "accelerator": "bvh", "small": "scenes/bunny.json",
//    "large": "@build/scenes/bunny_235k.json", "max_ratio": 8}
//        time of the same camera rays on a small and a large mesh
//
// Each test may carry "weight" (default 1): its share of the task's points.
// Errors name the file, line and column, and the allowed values.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ll::grading {

struct TestSpec {
  std::string kind;  // unit | image | complexity
  double weight = 1.0;
  std::string filter;          // unit: gtest filter
  std::string reference;       // image: "<dir>/<image>" under data/references
  nlohmann::json entry;        // image: the manifest entry (scene, size, set, tolerance, tasks)
  std::string technique;       // image: the manifest's technique
  std::string accelerator;     // complexity
  std::string small, large;    // complexity: scene paths under data/ ("@build/..." = under the build folder)
  double maxRatio = 8.0;       // complexity: largest allowed time(large) / time(small)
};

struct TaskSpec {
  std::string id;     // "A2.4"
  std::string title;
  double points = 0.0;
  bool optional = false;               // extra credit: its points are earned on top of the maximum
  std::string file;                    // the student's file, relative to the spec's folder
  std::vector<std::string> functions;  // what it defines (in ll::aN)
  std::vector<std::string> forbidden;  // names the file must not use (e.g. glm::lookAt for A1.1)
  std::vector<std::string> uses;       // other tasks its tests run -- by their references when it is graded
  std::vector<TestSpec> tests;
};

struct GradingSpec {
  std::string path;        // the grading.json
  std::string assignment;  // "A2"
  std::string title;
  std::vector<TaskSpec> tasks;
  std::string folder() const;                     // the spec's folder (assignments/a2_raycasting)
  std::vector<std::string> studentFiles() const;  // every task's file: what a submission replaces
};

// Loads one spec; image references are resolved against `dataDir`'s
// references/<dir>/references.json. Throws UserError with file:line:col.
GradingSpec loadGradingSpec(const std::string& path, const std::string& dataDir);

// The grading.json of every assignment under `assignmentsDir`, by folder name.
std::vector<std::string> findGradingSpecs(const std::string& assignmentsDir);

// The spec for `name`: an assignment ID ("A2", case-insensitive), a folder
// name ("a2_raycasting") or a path to a grading.json. Throws UserError
// listing the known assignments.
GradingSpec findGradingSpec(const std::string& name, const std::string& assignmentsDir, const std::string& dataDir);

}  // namespace ll::grading
