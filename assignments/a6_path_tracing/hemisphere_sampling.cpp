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
  // Your A6.1 here (see its comment in a6_tasks.h), then delete the line below.
  (void)u;
  LIGHTLAB_TODO("A6.1", "cosine-weighted hemisphere sampling (assignments/a6_path_tracing/hemisphere_sampling.cpp)");
  return Vec3(0.0f, 0.0f, 1.0f);
#endif
}

float cosineHemispherePdf(float cosTheta) {
#if LIGHTLAB_SOLUTION  // A6.1
  return cosTheta > 0.0f ? cosTheta / kPi : 0.0f;
#else
  // Your A6.1 here (see its comment in a6_tasks.h), then delete the line below.
  (void)cosTheta;
  LIGHTLAB_TODO("A6.1", "cosine-weighted hemisphere sampling (assignments/a6_path_tracing/hemisphere_sampling.cpp)");
  return 0.0f;
#endif
}

}  // namespace ll::a6
