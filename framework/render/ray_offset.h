// Robust origins for secondary rays (Wächter and Binder, "A Fast and Robust
// Method for Avoiding Self-Intersection", Ray Tracing Gems ch. 6): move the
// hit point off its surface by a few units in the last place of each
// coordinate, so the offset scales with the point's magnitude -- no fixed
// epsilon that is too big near the origin and too small far from it.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include "core/math.h"

namespace ll {

// p: a point on a surface; n: unit normal pointing to the side the new ray
// leaves towards. Returns p moved just off the surface on that side.
inline Vec3 offsetRayOrigin(const Vec3& p, const Vec3& n) {
  constexpr float kOrigin = 1.0f / 32.0f;       // below this magnitude, offset by a fixed amount
  constexpr float kFloatScale = 1.0f / 65536.0f;
  constexpr float kIntScale = 256.0f;           // ULPs moved per unit of normal
  Vec3 out;
  for (int i = 0; i < 3; ++i) {
    const auto ofs = static_cast<int32_t>(kIntScale * n[i]);
    const int32_t bits = std::bit_cast<int32_t>(p[i]) + (p[i] < 0.0f ? -ofs : ofs);
    out[i] = std::abs(p[i]) < kOrigin ? p[i] + kFloatScale * n[i] : std::bit_cast<float>(bits);
  }
  return out;
}

// The normal `n` flipped, if needed, to the side of direction `d`.
inline Vec3 faceTowards(const Vec3& n, const Vec3& d) { return glm::dot(n, d) < 0.0f ? -n : n; }

}  // namespace ll
