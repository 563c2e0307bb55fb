// An assignment's grading spec: assignments/<dir>/grading.json lists the
// tasks (ID, title, points) and, per task, the tests that grade it:
//
//   {"kind": "unit", "filter": "A2_4_*"}       gtest cases of lightlab_task_tests (each a test)
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
  std::vector<TestSpec> tests;
};

struct GradingSpec {
  std::string path;        // the grading.json
  std::string assignment;  // "A2"
  std::string title;
  std::vector<std::string> studentFiles;  // relative to the spec's folder: what a submission replaces
  std::vector<TaskSpec> tasks;
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
