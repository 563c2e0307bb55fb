// How big a scene may be. Positions and lengths are single-precision floats,
// and the intersection and shading code squares lengths twice (areas, then
// their lengths): with coordinates within +-1e8 scene units every such product
// stays below 1e32, far from the float limit of 3.4e38. Beyond it a sphere at
// 1e38 would overflow to a silently black image, so the loader and the GUI
// refuse such values as overflow.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/math.h"

namespace ll {

inline constexpr float kMaxSceneCoordinate = 1e8f;  // scene units
// A camera may stand farther out, to frame a scene that reaches the limit (a few radii away).
inline constexpr float kMaxCameraCoordinate = 1e9f;

// The largest |component| of v (NaN counts as too large).
inline float largestMagnitude(const Vec3& v) {
  if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))) return INFINITY;
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

inline bool withinSceneLimits(const Vec3& v) { return largestMagnitude(v) <= kMaxSceneCoordinate; }
inline bool withinCameraLimits(const Vec3& v) { return largestMagnitude(v) <= kMaxCameraCoordinate; }

}  // namespace ll
