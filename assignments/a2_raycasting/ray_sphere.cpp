// A2.2 Ray-sphere intersection.
#include "a2_tasks.h"
#include "render/student_task.h"

namespace ll::a2 {

bool raySphere(const Ray& ray, const Sphere& sphere, float& t) {
#if LIGHTLAB_SOLUTION  // A2.2
  // |o + t d - c|^2 = r^2  ->  a t^2 + 2 b' t + c = 0 with f = o - c.
  const Vec3 f = ray.origin - sphere.center;
  const float a = glm::dot(ray.dir, ray.dir);
  const float bPrime = glm::dot(f, ray.dir);
  const float c = glm::dot(f, f) - sphere.radius * sphere.radius;
  const float discriminant = bPrime * bPrime - a * c;
  if (discriminant < 0.0f) return false;
  // Stable roots: q has the sign of -b', so no cancellation.
  const float q = -bPrime - std::copysign(std::sqrt(discriminant), bPrime);
  float t0 = q / a;
  float t1 = q != 0.0f ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  if (t0 > ray.tmin && t0 < ray.tmax) {
    t = t0;
    return true;
  }
  if (t1 > ray.tmin && t1 < ray.tmax) {
    t = t1;
    return true;
  }
  return false;
#else
  // Your A2.2 here (see its comment in a2_tasks.h), then delete the line below.
  (void)ray;
  (void)sphere;
  (void)t;
  LIGHTLAB_TODO("A2.2", "ray-sphere intersection (assignments/a2_raycasting/ray_sphere.cpp)");
  return false;
#endif
}

}  // namespace ll::a2
