// Helpers shared by the GoogleTest files (tests/ is on their include path).
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/ray.h"
#include "render/student_task.h"

namespace ll::testing_support {

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
