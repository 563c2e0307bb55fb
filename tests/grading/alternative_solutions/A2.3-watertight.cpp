// An A2.3 the handout allows but the reference does not use: the watertight test of
// Woop, Benthin and Wald (JCGT 2013), written out by a student. It must score full
// marks: tests and tolerances accept every correct method (tests/student_tree/per_task_test.sh).
#include <cmath>
#include <utility>

#include "a2_tasks.h"

namespace ll::a2 {

bool rayTriangle(const Ray& ray, const Vec3& p0, const Vec3& p1, const Vec3& p2, float& t, float& b1, float& b2) {
  // Permute the axes so that z is the direction's largest component, then shear the ray onto +z.
  const Vec3 ad = glm::abs(ray.dir);
  const int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
  int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  if (ray.dir[kz] < 0.0f) std::swap(kx, ky);
  const float sx = ray.dir[kx] / ray.dir[kz], sy = ray.dir[ky] / ray.dir[kz], sz = 1.0f / ray.dir[kz];
  const Vec3 a = p0 - ray.origin, b = p1 - ray.origin, c = p2 - ray.origin;
  const float ax = a[kx] - sx * a[kz], ay = a[ky] - sy * a[kz];
  const float bx = b[kx] - sx * b[kz], by = b[ky] - sy * b[kz];
  const float cx = c[kx] - sx * c[kz], cy = c[ky] - sy * c[kz];
  double u = static_cast<double>(cx) * by - static_cast<double>(cy) * bx;
  double v = static_cast<double>(ax) * cy - static_cast<double>(ay) * cx;
  double w = static_cast<double>(bx) * ay - static_cast<double>(by) * ax;
  if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
  const double det = u + v + w;
  if (det == 0.0) return false;
  if (glm::cross(p1 - p0, p2 - p0) == Vec3(0.0f)) return false;  // degenerate: no normal to shade with
  const double tScaled = u * (sz * a[kz]) + v * (sz * b[kz]) + w * (sz * c[kz]);
  const float tHit = static_cast<float>(tScaled / det);
  if (!(tHit > ray.tmin && tHit < ray.tmax)) return false;
  t = tHit;
  b1 = static_cast<float>(v / det);
  b2 = static_cast<float>(w / det);
  return true;
}

}  // namespace ll::a2
