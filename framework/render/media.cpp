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
  return count == 0 ? 1.0f : scene.materials[ids[static_cast<size_t>(count - 1)]].ior;
}

Rgb Media::absorption(const Scene& scene) const {
  return count == 0 ? Rgb(0.0f) : scene.materials[ids[static_cast<size_t>(count - 1)]].absorption;
}

}  // namespace ll
