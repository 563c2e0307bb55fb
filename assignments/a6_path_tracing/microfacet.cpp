// A6.4 The GGX microfacet distribution: evaluating and sampling it.
#include <algorithm>
#include <cmath>

#include "a6_tasks.h"
#include "render/student_task.h"

namespace ll::a6 {

float ggxDistribution(const Vec3& h, float alpha) {
#if LIGHTLAB_SOLUTION  // A6.4
  if (h.z <= 0.0f) return 0.0f;
  // 1 / (pi a^2 cos^4 (1 + tan^2 / a^2)^2), written without the tangent (finite at h = n).
  const float a2 = alpha * alpha;
  const float d = h.z * h.z * (a2 - 1.0f) + 1.0f;
  return a2 / (kPi * d * d);
#else
  // Your A6.4 here (see its comment in a6_tasks.h), then delete the line below.
  (void)h;
  (void)alpha;
  LIGHTLAB_TODO("A6.4", "the GGX microfacet distribution (assignments/a6_path_tracing/microfacet.cpp)");
  return 0.0f;
#endif
}

float smithMasking(const Vec3& w, float alpha) {
#if LIGHTLAB_SOLUTION  // A6.4
  if (w.z <= 0.0f) return 0.0f;
  // 1 / (1 + Lambda) = 2 / (1 + sqrt(1 + a^2 tan^2)); multiplied through by cos (no tangent at grazing).
  const float a2 = alpha * alpha;
  return 2.0f * w.z / (w.z + std::sqrt(a2 + (1.0f - a2) * w.z * w.z));
#else
  // Your A6.4 here (see its comment in a6_tasks.h), then delete the line below.
  (void)w;
  (void)alpha;
  LIGHTLAB_TODO("A6.4", "the GGX microfacet distribution (assignments/a6_path_tracing/microfacet.cpp)");
  return 0.0f;
#endif
}

Vec3 sampleGgxVisibleNormal(const Vec3& wo, float alpha, Vec2 u) {
#if LIGHTLAB_SOLUTION  // A6.4
  // Heitz 2018: stretch the view to the hemisphere configuration (alpha = 1), ...
  const Vec3 v = glm::normalize(Vec3(alpha * wo.x, alpha * wo.y, wo.z));
  const float lengthSq = v.x * v.x + v.y * v.y;
  const Vec3 t1 = lengthSq > 0.0f ? Vec3(-v.y, v.x, 0.0f) / std::sqrt(lengthSq) : Vec3(1.0f, 0.0f, 0.0f);
  const Vec3 t2 = glm::cross(v, t1);
  // ... a uniform point on the disk, its lower half squeezed onto the visible part of the projected hemisphere, ...
  const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
  const float p1 = r * std::cos(phi);
  const float s = 0.5f * (1.0f + v.z);
  const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
  const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * v;
  // ... lifted onto the hemisphere and unstretched.
  return glm::normalize(Vec3(alpha * nh.x, alpha * nh.y, std::max(1e-6f, nh.z)));
#else
  // Your A6.4 here (see its comment in a6_tasks.h), then delete the line below.
  (void)wo;
  (void)alpha;
  (void)u;
  LIGHTLAB_TODO("A6.4", "the GGX microfacet distribution (assignments/a6_path_tracing/microfacet.cpp)");
  return Vec3(0.0f, 0.0f, 1.0f);
#endif
}

}  // namespace ll::a6
