// What a technique uses to query the scene: the accelerator plus per-worker
// counters, so every ray is counted by kind without synchronisation.
#pragma once

#include "accel/accelerator.h"
#include "render/render_stats.h"
#include "scene/scene.h"

namespace ll {

class Tracer {
 public:
  Tracer(const Scene& scene, const Accelerator& accel, WorkCounters& counters)
      : scene_(scene), accel_(accel), counters_(counters) {}

  const Scene& scene() const { return scene_; }

  // Closest hit in (ray.tmin, ray.tmax), counted as a ray of `kind`.
  bool intersect(const Ray& ray, Hit& hit, RayKind kind) const {
    ++counters_.rays[static_cast<size_t>(kind)];
    return accel_.intersect(ray, hit, counters_.query);
  }
  // Any hit in (ray.tmin, ray.tmax); shadow rays by default.
  bool occluded(const Ray& ray, RayKind kind = RayKind::Shadow) const {
    ++counters_.rays[static_cast<size_t>(kind)];
    return accel_.occluded(ray, counters_.query);
  }

 private:
  const Scene& scene_;
  const Accelerator& accel_;
  WorkCounters& counters_;
};

}  // namespace ll
