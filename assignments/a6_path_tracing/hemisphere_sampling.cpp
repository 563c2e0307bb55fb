// A6.1 Cosine-weighted hemisphere sampling.
#include <algorithm>
#include <cmath>

#include "a6_tasks.h"
#include "render/student_task.h"

namespace ll::a6 {

Vec3 sampleCosineHemisphere(Vec2 u) {
#if LIGHTLAB_SOLUTION  // A6.1
  // Malley: a uniform point on the unit disk (r = sqrt(u.x) keeps the area
  // uniform), lifted straight up onto the hemisphere.
  const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x))};
#else
  LIGHTLAB_TODO("A6.1", "cosine-weighted hemisphere sampling (assignments/a6_path_tracing/hemisphere_sampling.cpp)");
  // Stand-in: uniform over the hemisphere (density 1 / 2 pi): correct, noisier.
  const float z = u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
#endif
}

float cosineHemispherePdf(float cosTheta) {
#if LIGHTLAB_SOLUTION  // A6.1
  return cosTheta > 0.0f ? cosTheta / kPi : 0.0f;
#else
  LIGHTLAB_TODO("A6.1", "cosine-weighted hemisphere sampling (assignments/a6_path_tracing/hemisphere_sampling.cpp)");
  return cosTheta > 0.0f ? 1.0f / (2.0f * kPi) : 0.0f;  // the stand-in's uniform density
#endif
}

}  // namespace ll::a6
