// Rays and ray kinds. A ray is the half-line origin + t*dir for t in [tmin, tmax].
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "core/math.h"

namespace ll {

struct Ray {
  Vec3 origin{0.0f};
  Vec3 dir{0.0f, 0.0f, 1.0f};  // need not be unit length; t is in units of |dir|
  float tmin = 0.0f;
  float tmax = kInfinity;
  Vec3 at(float t) const { return origin + t * dir; }
};

// Why a ray was cast; statistics count rays by kind.
enum class RayKind : uint8_t { Camera, Shadow, Reflection, Refraction, Indirect };
constexpr int kRayKindCount = 5;
constexpr std::array<std::string_view, kRayKindCount> kRayKindNames = {
    "camera", "shadow", "reflection", "refraction", "indirect"};

// Closest hit as an accelerator reports it: distance, primitive and the
// primitive's own surface coordinates (barycentrics b1, b2 of vertices 1 and 2
// for triangles; unused for spheres). The scene turns it into a SurfacePoint.
struct Hit {
  static constexpr uint32_t kNone = 0xffffffffu;
  float t = kInfinity;
  uint32_t prim = kNone;
  float b1 = 0.0f, b2 = 0.0f;
  bool valid() const { return prim != kNone; }
};

}  // namespace ll
