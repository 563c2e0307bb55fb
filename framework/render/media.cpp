#include "render/media.h"

namespace ll {

Media Media::with(uint32_t material) const {
  Media m = *this;
  if (m.count < kMax) m.ids[static_cast<size_t>(m.count++)] = material;
  return m;
}

Media Media::without(uint32_t material) const {
  Media m = *this;
  for (int i = m.count - 1; i >= 0; --i)
    if (m.ids[static_cast<size_t>(i)] == material) {
      for (int k = i; k + 1 < m.count; ++k) m.ids[static_cast<size_t>(k)] = m.ids[static_cast<size_t>(k + 1)];
      --m.count;
      break;
    }
  return m;
}

float Media::ior(const Scene& scene) const {
  const Material* m = innermost(scene);
  return m ? m->ior : 1.0f;
}

Rgb Media::absorption(const Scene& scene) const {
  const Material* m = innermost(scene);
  return m ? m->absorption : Rgb(0.0f);
}

}  // namespace ll
