// Cheat: A2.3 handed in as the framework's own watertight triangle test.
#include "a2_tasks.h"

namespace ll::a2 {
bool rayTriangle(const Ray& ray, const Vec3& p0, const Vec3& p1, const Vec3& p2, float& t, float& b1, float& b2) {
  return intersectTriangle(WatertightRay(ray), p0, p1, p2, ray.tmin, ray.tmax, t, b1, b2);
}
}  // namespace ll::a2
