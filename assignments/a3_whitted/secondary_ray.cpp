// A3.5 Origins of secondary rays that never re-hit their own surface.
#include "a3_tasks.h"
#include "render/ray_offset.h"
#include "render/student_task.h"

namespace ll::a3 {

Ray secondaryRay(Vec3 p, Vec3 ng, Vec3 dir) {
  Ray ray;
  ray.dir = dir;
  ray.tmin = 0.0f;
  ray.tmax = kInfinity;
#if LIGHTLAB_SOLUTION  // A3.5
  ray.origin = offsetRayOrigin(p, faceTowards(ng, dir));
#else
  LIGHTLAB_TODO("A3.5", "secondary-ray origins (assignments/a3_whitted/secondary_ray.cpp)");
  ray.origin = p + 1e-4f * faceTowards(ng, dir);  // stand-in: one fixed epsilon (acne far from the origin)
#endif
  return ray;
}

}  // namespace ll::a3
