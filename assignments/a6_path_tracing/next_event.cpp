// A6.2 Next-event estimation (direct light from one light sample, with MIS).
#include <cmath>

#include "a6_tasks.h"
#include "render/student_task.h"

namespace ll::a6 {

Rgb nextEventEstimate(const ShadingPoint& x, const LightSample& light, const Bsdf& bsdf, const Tracer& tracer,
                      bool mis) {
#if LIGHTLAB_SOLUTION  // A6.2
  Vec3 wi;
  float distance = kInfinity;
  Rgb arriving;  // radiance (area) or irradiance (delta lights) arriving along wi, divided by the density
  float weight = 1.0f;
  switch (light.kind) {
    case LightSample::Kind::Area: {
      const Vec3 d = light.position - x.position;
      distance = glm::length(d);
      if (!(distance > 0.0f)) return Rgb(0.0f);
      wi = d / distance;
      const float cosLight = glm::dot(light.normal, -wi);
      if (cosLight <= 0.0f) return Rgb(0.0f);  // behind the emitting side
      const float pdf = light.pdf * distance * distance / cosLight;  // area -> solid angle
      if (mis) weight = powerHeuristic(pdf, bsdf.pdf(x.wo, wi));
      arriving = light.emission / pdf;
      break;
    }
    case LightSample::Kind::Point: {
      const Vec3 d = light.position - x.position;
      distance = glm::length(d);
      if (!(distance > 0.0f)) return Rgb(0.0f);
      wi = d / distance;
      arriving = kPi * light.emission / (distance * distance * light.pdf);
      break;
    }
    case LightSample::Kind::Directional:
      wi = -light.direction;
      arriving = kPi * light.emission / light.pdf;
      break;
  }
  const float cosSurface = glm::dot(x.n, wi);
  if (cosSurface <= 0.0f || glm::dot(x.ng, wi) <= 0.0f) return Rgb(0.0f);  // the light is behind x
  const Rgb f = bsdf.eval(x.wo, wi);
  if (isBlack(f)) return Rgb(0.0f);  // no shadow ray where nothing would be added
  if (light.castShadow && !visible(tracer, x, wi, distance)) return Rgb(0.0f);
  return f * cosSurface * arriving * weight;
#else
  // Your A6.2 here (see its comment in a6_tasks.h), then delete the line below.
  (void)x;
  (void)light;
  (void)bsdf;
  (void)tracer;
  (void)mis;
  LIGHTLAB_TODO("A6.2", "next-event estimation (assignments/a6_path_tracing/next_event.cpp)");
  return Rgb(0.0f);
#endif
}

}  // namespace ll::a6
