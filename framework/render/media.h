// The dielectrics a path is inside, innermost last (material indices), for
// techniques that refract (Whitted, path tracing). Nested glass (a glass
// sphere in water) needs the whole stack: leaving the glass puts the ray back
// into the water, not into air.
#pragma once

#include <array>
#include <cstdint>

#include "core/math.h"
#include "scene/scene.h"

namespace ll {

struct Media {
  static constexpr int kMax = 8;  // deeper nesting keeps the 8 outermost
  std::array<uint32_t, kMax> ids{};
  int count = 0;
  Media with(uint32_t material) const;     // entered `material`
  Media without(uint32_t material) const;  // left it (the innermost occurrence)
  // The innermost medium's material, or nullptr outside everything.
  const Material* innermost(const Scene& scene) const {
    return count == 0 ? nullptr : &scene.materials[ids[static_cast<size_t>(count - 1)]];
  }
  // Refractive index of the innermost medium (1 = vacuum/air outside everything).
  float ior(const Scene& scene) const;
  // Beer-Lambert coefficient of the innermost medium, 1 / scene unit (0 outside).
  Rgb absorption(const Scene& scene) const;
};

}  // namespace ll
