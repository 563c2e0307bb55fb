// Numerically careful ray/sphere intersection (Haines et al., "Precision
// Improvements for Ray/Sphere Intersection", Ray Tracing Gems ch. 7): the
// discriminant is formed from the distance of the centre to the ray's line,
// and the near root uses the stable quadratic form, so far-away and tiny
// spheres keep their precision. It answers task A2.2, so the student tree
// holds it as object code only (tasks/framework_answer.h).
#pragma once

#include <cmath>

#include "core/ray.h"
#include "tasks/framework_answer.h"

namespace ll {

// Tests the sphere (center, radius) for t in (tmin, tmax); returns the nearest
// such t. Hits from inside return the exit point.
bool intersectSphere(const Ray& ray, const Vec3& center, float radius, float tmin, float tmax, float& t);

#if !LIGHTLAB_STUDENT_TREE  // A2.2's answer: object code only in the student tree
LIGHTLAB_ANSWER_INLINE bool intersectSphere(const Ray& ray, const Vec3& center, float radius, float tmin, float tmax,
                                            float& t) {
  LIGHTLAB_ANSWER_GUARD("A2.2", "ll::intersectSphere (the framework's sphere test)");
  const Vec3 f = ray.origin - center;
  const float a = glm::dot(ray.dir, ray.dir);
  const float bPrime = -glm::dot(f, ray.dir);  // b' = -b/2
  const Vec3 l = f + (bPrime / a) * ray.dir;    // centre-to-line vector
  const float discriminant = a * (radius * radius - glm::dot(l, l));
  if (discriminant < 0.0f) return false;
  const float c = glm::dot(f, f) - radius * radius;
  const float q = bPrime + std::copysign(std::sqrt(discriminant), bPrime);
  float t0 = q == 0.0f ? 0.0f : c / q;
  float t1 = q / a;
  if (t0 > t1) std::swap(t0, t1);
  if (t0 > tmin && t0 < tmax) {
    t = t0;
    return true;
  }
  if (t1 > tmin && t1 < tmax) {
    t = t1;
    return true;
  }
  return false;
}
#endif

}  // namespace ll
