// A2.3 Ray-triangle intersection.
#include "a2_tasks.h"
#include "render/student_task.h"

namespace ll::a2 {

bool rayTriangle(const Ray& ray, const Vec3& p0, const Vec3& p1, const Vec3& p2, float& t, float& b1,
                 float& b2) {
#if LIGHTLAB_SOLUTION  // A2.3
  // Moeller-Trumbore: solve o + t d = p0 + b1 (p1 - p0) + b2 (p2 - p0) by Cramer's rule.
  const Vec3 e1 = p1 - p0, e2 = p2 - p0;
  const Vec3 pvec = glm::cross(ray.dir, e2);
  const float det = glm::dot(e1, pvec);
  if (det == 0.0f) return false;  // ray parallel to the plane (or a degenerate triangle)
  const float invDet = 1.0f / det;
  const Vec3 tvec = ray.origin - p0;
  const float u = glm::dot(tvec, pvec) * invDet;
  if (u < 0.0f || u > 1.0f) return false;
  const Vec3 qvec = glm::cross(tvec, e1);
  const float v = glm::dot(ray.dir, qvec) * invDet;
  if (v < 0.0f || u + v > 1.0f) return false;
  const float tHit = glm::dot(e2, qvec) * invDet;
  if (!(tHit > ray.tmin && tHit < ray.tmax)) return false;
  t = tHit;
  b1 = u;
  b2 = v;
  return true;
#else
  // Your A2.3 here (see its comment in a2_tasks.h), then delete the line below.
  (void)ray;
  (void)p0;
  (void)p1;
  (void)p2;
  (void)t;
  (void)b1;
  (void)b2;
  LIGHTLAB_TODO("A2.3", "ray-triangle intersection (assignments/a2_raycasting/ray_triangle.cpp)");
  return false;
#endif
}

}  // namespace ll::a2
