#include "render/shadow_transmittance.h"

#include <algorithm>
#include <cmath>

#include "render/ray_offset.h"

namespace ll {

Rgb filteredShadowTransmittance(const Scene& scene, const Tracer& tracer, const Ray& shadow, const Media& start) {
  Rgb through(1.0f);
  Media media = start;
  Ray r = shadow;
  for (int crossings = 0;; ++crossings) {
    Hit hit;
    const bool hitSomething = tracer.intersect(r, hit, RayKind::Shadow);
    const Rgb sigma = media.absorption(scene);
    if (!hitSomething) {
      // The last segment, to the light; a directional light seen from inside an absorbing medium is dark.
      if (!isBlack(sigma)) through *= std::isinf(r.tmax) ? Rgb(0.0f) : glm::exp(-sigma * r.tmax);
      return through;
    }
    const Material& m = scene.materialOf(hit.prim);
    if (!m.transmits() || crossings == kMaxShadowCrossings) return Rgb(0.0f);
    const SurfacePoint sp = scene.surfacePoint(r, hit);
    const float travelled = glm::length(sp.position - r.origin);
    if (!isBlack(sigma)) through *= glm::exp(-sigma * travelled);
    through *= m.transmission;
    const auto id = static_cast<uint32_t>(&m - scene.materials.data());
    media = glm::dot(sp.geometricNormal, r.dir) < 0.0f ? media.with(id) : media.without(id);
    if (isBlack(through)) return through;
    r.origin = offsetRayOrigin(sp.position, faceTowards(sp.geometricNormal, r.dir));
    r.tmax = std::max(0.0f, r.tmax - travelled);
    if (!(r.tmax > 0.0f)) return through;
  }
}

}  // namespace ll
