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
  // Your A3.5 here (see its comment in a3_tasks.h), then delete the line below.
  (void)ng;
  LIGHTLAB_TODO("A3.5", "secondary-ray origins (assignments/a3_whitted/secondary_ray.cpp)");
  ray.origin = p;
#endif
  return ray;
}

}  // namespace ll::a3
