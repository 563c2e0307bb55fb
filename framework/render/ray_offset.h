// Robust origins for secondary rays: move the hit point off its surface by a
// distance that scales with the rounding error of its coordinates -- no fixed
// epsilon that is too big near the origin and too small far from it (the idea
// of Wächter and Binder, "A Fast and Robust Method for Avoiding
// Self-Intersection", Ray Tracing Gems ch. 6, with the distance bounded from
// the point's error as in pbrt-v4's OffsetRayOrigin).
//
// A hit point from barycentric interpolation (triangles) or reprojection
// (spheres) is off the true surface by at most ~3 float ulps of each
// coordinate, so its distance to the surface along n is at most
// 3 sum_i |n_i| ulp(p_i) (here ulp of the largest |p_i|, see below). Moving by kUlps = 8 times that, plus a floor for
// points near the origin, clears the surface with room to spare while
// staying small: about 0.1 scene units at 1e5 (Wächter and Binder's 256 ulps
// per axis move ~2 units there, more than a small object's size).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/math.h"

namespace ll {

// p: a point on a surface; n: unit normal pointing to the side the new ray
// leaves towards. Returns p moved just off the surface on that side.
// The error is measured in ulps of p's largest coordinate, not of each one: a point
// on the plane x = 0 of a wall 500 units across has an exact x, but a ray leaving it
// is tested against that wall in coordinates of size 500, where the triangle test's
// t rounds by ~1e-4 -- a move by ulp(0) re-hit the wall (speckled shadow acne on the
// Cornell box's right wall, lit by a point light; numerics/self_intersection_test).
inline Vec3 offsetRayOrigin(const Vec3& p, const Vec3& n) {
  constexpr float kUlps = 8.0f;              // error bounds moved, along n
  constexpr float kFloor = 1.0f / 65536.0f;  // scene units: the least move (points near the origin)
  const float a = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const float ulp = std::nextafter(a, std::numeric_limits<float>::infinity()) - a;
  const float error = (std::abs(n.x) + std::abs(n.y) + std::abs(n.z)) * ulp;  // bound along n
  return p + (kFloor + kUlps * error) * n;
}

// The normal `n` flipped, if needed, to the side of direction `d`.
inline Vec3 faceTowards(const Vec3& n, const Vec3& d) { return glm::dot(n, d) < 0.0f ? -n : n; }

}  // namespace ll
