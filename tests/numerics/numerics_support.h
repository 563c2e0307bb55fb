// Helpers of the hard-case suite (tests/numerics): hand-made geometry, every
// accelerator of the registry built over it, and double-precision references.
#pragma once

#include "test_support.h"

#include <memory>
#include <string>
#include <vector>

#include "accel/accelerator.h"
#include "modules/registry.h"
#include "scene/geometry.h"

namespace ll::numerics {

// One accelerator of the registry, built with its default parameters.
struct BuiltAccelerator {
  std::string name;
  std::unique_ptr<Accelerator> accel;
  // Embree uses its own triangle test: exact answers are demanded of it only
  // away from triangle edges and vertices (see a4_test.cpp and accel_measurements.md).
  bool exactOnEdges() const { return name != "embree"; }
};

// While in scope, everyAccelerator() builds only `name`: a task's graded hard cases run the
// shared cases on the structure that task traverses.
inline std::string& onlyAcceleratorName() {
  static std::string name;
  return name;
}
class OnlyAccelerator {
 public:
  explicit OnlyAccelerator(std::string name) : previous_(onlyAcceleratorName()) { onlyAcceleratorName() = std::move(name); }
  ~OnlyAccelerator() { onlyAcceleratorName() = previous_; }
  OnlyAccelerator(const OnlyAccelerator&) = delete;
  OnlyAccelerator& operator=(const OnlyAccelerator&) = delete;

 private:
  std::string previous_;
};

inline std::vector<BuiltAccelerator> everyAccelerator(const Geometry& g) {
  std::vector<BuiltAccelerator> out;
  for (const AcceleratorInfo& info : accelerators())
    if (onlyAcceleratorName().empty() || info.name == onlyAcceleratorName())
      out.push_back({info.name, buildAccelerator(info, ParamSet("accelerator '" + info.name + "'", info.params), g)});
  return out;
}

inline uint32_t addTriangle(Geometry& g, Vec3 a, Vec3 b, Vec3 c, uint32_t object = 0) {
  const auto base = static_cast<uint32_t>(g.positions.size());
  g.positions.insert(g.positions.end(), {a, b, c});
  g.triangles.emplace_back(base, base + 1, base + 2);
  g.triangleObject.push_back(object);
  return g.triangleCount() - 1;
}

// The parallelogram o, o + e1, o + e1 + e2, o + e2 as two triangles sharing the diagonal.
inline void addQuad(Geometry& g, Vec3 o, Vec3 e1, Vec3 e2, uint32_t object = 0) {
  addTriangle(g, o, o + e1, o + e1 + e2, object);
  addTriangle(g, o, o + e1 + e2, o + e2, object);
}

inline void addSphere(Geometry& g, Vec3 c, float r, uint32_t object = 0) {
  g.spheres.push_back({c, r});
  g.sphereObject.push_back(object);
}

// A closed fan around `centre`: triangle k = (centre, rim[k], rim[k+1 mod n]), sharing vertices by index.
inline Geometry fan(const Vec3& centre, const std::vector<Vec3>& rim) {
  Geometry g;
  g.positions.push_back(centre);
  g.positions.insert(g.positions.end(), rim.begin(), rim.end());
  const auto n = static_cast<unsigned>(rim.size());
  for (unsigned k = 0; k < n; ++k) {
    g.triangles.emplace_back(0u, 1u + k, 1u + (k + 1) % n);
    g.triangleObject.push_back(0);
  }
  return g;
}

// A ray with every field given (test_support.h's makeRay under a short name).
inline Ray ray(Vec3 origin, Vec3 dir, float tmin = 0.0f, float tmax = kInfinity) {
  return testing_support::makeRay(origin, dir, tmin, tmax);
}

}  // namespace ll::numerics
