// A3.4 The recursion: trace(p, d, step) of the lecture.
#include "a3_tasks.h"
#include "render/student_task.h"
#include "whitted_tracer.h"

namespace ll::a3 {

Rgb radiance(const WhittedTracer& tracer, const Ray& ray, const PathState& path) {
#if LIGHTLAB_SOLUTION  // A3.4
  if (path.depth > tracer.maxDepth() || maxComponent(path.throughput) < tracer.minThroughput()) return Rgb(0.0f);
  const std::optional<Surface> s = tracer.intersect(ray, path);
  if (!s) return tracer.background(ray);
  const Material& m = s->material();
  Rgb l = tracer.emitted(*s) + tracer.local(*s);
  const Vec3 p = s->sp.position;
  if (m.reflectsMirror())
    l += tracer.trace(secondaryRay(p, s->ng, reflect(s->d, s->n)), RayKind::Reflection, *s, m.mirror);
  if (m.transmits()) {
    Vec3 t;
    const bool refracts = refract(s->d, s->n, s->n1 / s->n2, t);
    const float f = refracts ? tracer.fresnel(*s) : 1.0f;  // total internal reflection: all is reflected
    l += tracer.trace(secondaryRay(p, s->ng, reflect(s->d, s->n)), RayKind::Reflection, *s, f * m.transmission);
    if (refracts && f < 1.0f)
      l += tracer.trace(secondaryRay(p, s->ng, t), RayKind::Refraction, *s, (1.0f - f) * m.transmission);
  }
  return s->absorption * l;  // Beer-Lambert along the way here
#else
  // Your A3.4 here (see its comment in a3_tasks.h), then delete the line below.
  (void)tracer;
  (void)ray;
  (void)path;
  LIGHTLAB_TODO("A3.4", "the recursion (assignments/a3_whitted/radiance.cpp)");
  return Rgb(0.0f);
#endif
}

}  // namespace ll::a3
