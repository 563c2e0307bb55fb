// LIGHTLAB_ANSWER_FILE A2.5: visible(), the path tracer's shadow ray (light_sampler.h). It
// answers task A2.5, so the student tree holds this file as object code only.
#include <cmath>

#include "light_sampler.h"
#include "render/ray_offset.h"
#include "tasks/framework_answer.h"

namespace ll::a6 {

bool visible(const Tracer& tracer, const ShadingPoint& x, const Vec3& wi, float distance) {
  LIGHTLAB_ANSWER_GUARD("A2.5", "ll::a6::visible (the path tracer's shadow ray)");
  Ray ray;
  ray.origin = offsetRayOrigin(x.position, faceTowards(x.ng, wi));
  ray.dir = wi;
  ray.tmin = 0.0f;
  ray.tmax = std::isinf(distance) ? kInfinity : distance * (1.0f - 1e-4f);
  return !tracer.occluded(ray);
}

}  // namespace ll::a6
