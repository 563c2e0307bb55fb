// A2.5 Shadow rays.
#include "a2_tasks.h"
#include "render/ray_offset.h"
#include "render/student_task.h"

namespace ll::a2 {

Ray shadowRay(const SurfacePoint& sp, const Vec3& toLight, float distance) {
#if LIGHTLAB_SOLUTION  // A2.5
  Ray ray;
  // Leave the surface on the light's side, offset relative to the point's magnitude.
  ray.origin = offsetRayOrigin(sp.position, faceTowards(sp.geometricNormal, toLight));
  ray.dir = toLight;
  ray.tmin = 0.0f;
  // Stop just short of the light so the light's own surface never blocks it.
  ray.tmax = std::isinf(distance) ? kInfinity : distance * (1.0f - 1e-4f);
  return ray;
#else
  (void)toLight;
  (void)distance;
  LIGHTLAB_TODO("A2.5", "shadow rays (assignments/a2_raycasting/shadow_ray.cpp)");
  Ray none;  // an empty interval: nothing is ever in shadow until this is written
  none.origin = sp.position;
  none.tmin = 0.0f;
  none.tmax = 0.0f;
  return none;
#endif
}

}  // namespace ll::a2
