// Helpers shared by the GoogleTest files (tests/ is on their include path).
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <cstdlib>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include <glm/gtc/matrix_access.hpp>
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/ray.h"
#include "render/student_task.h"
#include "tasks/task_catalog.h"
#include "tasks/task_modes.h"

namespace ll::testing_support {

// A hit as a failure message states it: "primitive 166 at t = 0.587939262", or "no hit".
inline std::string describeHit(const Hit& h) {
  if (!h.valid()) return "no hit";
  char t[32];
  std::snprintf(t, sizeof t, "%.9g", static_cast<double>(h.t));
  return "primitive " + std::to_string(h.prim) + " at t = " + t;
}

// The seed of the task tests' random inputs: $LIGHTLAB_GRADING_SEED, else 1. The
// autograder sets its own (the student tree does not hold it), so a lookup table of
// the inputs a student can see earns nothing.
inline uint32_t gradingSeed() {
  const char* s = std::getenv("LIGHTLAB_GRADING_SEED");
  return s && *s ? static_cast<uint32_t>(std::strtoul(s, nullptr, 10)) : 1u;
}

// A random stream for one test: the grading seed mixed with the test's own salt.
inline std::mt19937 gradingRng(uint32_t salt) {
  std::seed_seq seq{gradingSeed(), salt};
  return std::mt19937(seq);
}

// What `f` returns with task `id` run by its reference (then the task's mode is as
// before): the expected values of tests on random inputs. In the solution tree the
// reference is the very same code.
template <class F>
auto byReference(const char* id, F&& f) {
  const int task = tasks::requireTask(id);
  const tasks::Mode before = tasks::mode(task);
  tasks::setMode(task, tasks::Mode::Reference);
  struct Restore {
    int task;
    tasks::Mode mode;
    ~Restore() { tasks::setMode(task, mode); }
  } restore{task, before};
  return f();
}

// The command that follows pixel (x, y) of `scene` rendered at width x height, with the running
// test's task isolated (its suite names it), for a failure message a student can paste.
inline std::string traceCommand(const std::string& scene, int x, int y, int width, int height,
                                const std::string& technique = "raycast") {
  std::string rel = scene;
  const auto at = rel.rfind("/data/");
  if (at != std::string::npos) rel = rel.substr(at + 1);
  std::string isolate;
  if (const testing::TestInfo* info = testing::UnitTest::GetInstance()->current_test_info()) {
    const int task = tasks::taskOfTestSuite(info->test_suite_name());
    if (task >= 0) isolate = std::string("--isolate ") + tasks::taskCatalog()[static_cast<size_t>(task)].id + " ";
  }
  return "build/lightlab " + isolate + "trace " + rel + " --pixel " + std::to_string(x) + " " + std::to_string(y) +
         " --width " + std::to_string(width) + " --height " + std::to_string(height) + " -t " + technique + " --json";
}

// A failing ray against one triangle or one sphere, as a scene file a student can trace: writes
// $LIGHTLAB_CASES_DIR (default out/cases)/<test>.json and returns the `lightlab trace --ray`
// command that follows the ray with the running test's task isolated. For failure messages
// (GoogleTest evaluates them only when the check fails).
inline std::string traceCase(const Ray& ray, const std::vector<Vec3>& triangle, const Vec3& centre = Vec3(0.0f),
                             float radius = 0.0f) {
  const char* dir = std::getenv("LIGHTLAB_CASES_DIR");
  const std::string folder = dir && *dir ? dir : "out/cases";
  std::string name = "case", isolate;
  if (const testing::TestInfo* info = testing::UnitTest::GetInstance()->current_test_info()) {
    name = std::string(info->test_suite_name()) + "." + info->name();
    for (char& c : name)
      if (c == '/') c = '_';
    const int task = tasks::taskOfTestSuite(info->test_suite_name());
    if (task >= 0) isolate = std::string("--isolate ") + tasks::taskCatalog()[static_cast<size_t>(task)].id + " ";
  }
  const std::string path = folder + "/" + name + ".json";
  const auto num = [](float v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.9g", static_cast<double>(v));
    return std::string(b);
  };
  const auto vec = [&](const Vec3& v) { return "[" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + "]"; };
  std::string object;
  if (triangle.size() == 3)
    object = R"({"type": "triangles", "name": "the triangle", "material": "grey", "positions": [)" + vec(triangle[0]) +
             ", " + vec(triangle[1]) + ", " + vec(triangle[2]) + R"(], "indices": [[0, 1, 2]]})";
  else
    object = R"({"type": "sphere", "name": "the sphere", "material": "grey", "center": )" + vec(centre) +
             ", \"radius\": " + num(radius) + "}";
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  std::ofstream(path) << R"({"description": "The failing case of )" << name << R"(: trace the ray with the command of the failure message.",
  "camera": {"eye": )" << vec(ray.origin) << R"(, "target": )" << vec(ray.origin + ray.dir) << R"(, "up": [0.3, 1, 0.2], "fov_y_deg": 40, "width": 64, "height": 64},
  "materials": {"grey": {"kd": [0.5, 0.5, 0.5]}},
  "lights": [{"type": "directional", "direction": [0, -1, 0], "intensity": [1, 1, 1]}],
  "objects": [)" << object << "]}\n";
  return "trace it: build/lightlab " + isolate + "trace " + path + " --ray " + num(ray.origin.x) + " " +
         num(ray.origin.y) + " " + num(ray.origin.z) + " " + num(ray.dir.x) + " " + num(ray.dir.y) + " " +
         num(ray.dir.z) + " --json";
}

// A random unit vector (uniform on the sphere) from `rng`.
inline Vec3 randomUnitVector(std::mt19937& rng) {
  std::normal_distribution<float> g;
  for (;;) {
    const Vec3 v(g(rng), g(rng), g(rng));
    if (glm::length(v) > 1e-3f) return glm::normalize(v);
  }
}

// A translation by whole units, in [-8, 8]^3, drawn from the grading seed: tests move
// their whole set-up by it (the answers do not change) so that their inputs are not
// the ones the student tree shows.
inline Vec3 gradingOffset(uint32_t salt) {
  std::mt19937 rng = gradingRng(salt);
  std::uniform_int_distribution<int> k(-8, 8);
  return Vec3(static_cast<float>(k(rng)), static_cast<float>(k(rng)), static_cast<float>(k(rng)));
}

// The message of the UserError `f` throws ("" and a test failure if none).
template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a UserError";
  return "";
}

inline bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// A ray with every field given (Ray has no constructor).
inline Ray makeRay(Vec3 origin, Vec3 dir, float tmin = 0.0f, float tmax = kInfinity) {
  Ray r;
  r.origin = origin;
  r.dir = dir;
  r.tmin = tmin;
  r.tmax = tmax;
  return r;
}

// Success if calling `probe` did not run the stub of task `id`.
template <class F>
testing::AssertionResult implemented(const char* id, F&& probe) {
  TaskLog log;
  {
    const ScopedTaskLog scope(&log);
    probe();
  }
  const auto missing = log.missing();
  const auto it = missing.find(id);
  if (it == missing.end()) return testing::AssertionSuccess();
  return testing::AssertionFailure() << id << " not implemented (" << it->second << ")";
}

}  // namespace ll::testing_support

// How GoogleTest prints the framework's values in a failure: as decimal numbers.
namespace glm {
template <length_t L, typename T, qualifier Q>
void PrintTo(const vec<L, T, Q>& v, std::ostream* os) {
  *os << "(";
  for (length_t i = 0; i < L; ++i) *os << (i ? ", " : "") << v[i];
  *os << ")";
}
template <length_t C, length_t R, typename T, qualifier Q>
void PrintTo(const mat<C, R, T, Q>& m, std::ostream* os) {
  *os << "[";
  for (length_t r = 0; r < R; ++r) {
    *os << (r ? "; " : "");
    for (length_t c = 0; c < C; ++c) *os << (c ? " " : "") << m[c][r];
  }
  *os << "]";
}
}  // namespace glm

namespace ll {
inline void PrintTo(const Ray& r, std::ostream* os) {
  *os << "ray from (" << r.origin.x << ", " << r.origin.y << ", " << r.origin.z << ") along (" << r.dir.x << ", "
      << r.dir.y << ", " << r.dir.z << "), t in (" << r.tmin << ", " << r.tmax << ")";
}
}  // namespace ll
