// Filtered shadow rays absorb by Beer-Lambert along their path through glass
// and water (render/shadow_transmittance.h), in `raycast` and `whitted`: a
// floor lit straight down through slabs of known thickness and sigma is
// darkened by exactly exp(-sum of sigma x thickness), nested media included.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "render_support.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

using testing_support::renderSettings;
using testing_support::renderWith;

// A horizontal slab between heights y0 < y1, normals outwards (top +y, bottom -y).
std::string slab(const std::string& name, const std::string& material, float y0, float y1) {
  const std::string a = std::to_string(y0), b = std::to_string(y1);
  return R"({"type": "quad", "name": ")" + name + R"(_top", "material": ")" + material +
         R"(", "vertices": [[-50, )" + b + R"(, -50], [-50, )" + b + R"(, 50], [50, )" + b + R"(, 50], [50, )" + b +
         R"(, -50]]},
      {"type": "quad", "name": ")" + name + R"(_bottom", "material": ")" + material +
         R"(", "vertices": [[-50, )" + a + R"(, -50], [50, )" + a + R"(, -50], [50, )" + a + R"(, 50], [-50, )" + a +
         R"(, 50]]})";
}

// The floor at y = 0 seen from below the slabs, a point light at y = 10 straight above its centre.
Scene slabScene(const std::string& water, const std::string& glass) {
  return parseJsonScene(R"({
    "camera": {"eye": [0, 0.5, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 2, "width": 9, "height": 9},
    "materials": {"floor": {"kd": [1, 1, 1]}, "water": )" + water + R"(, "glass": )" + glass + R"(},
    "lights": [{"type": "point", "position": [0, 10, 0], "intensity": [100, 100, 100]}],
    "objects": [
      {"type": "quad", "name": "floor", "material": "floor", "vertices": [[-5, 0, -5], [-5, 0, 5], [5, 0, 5], [5, 0, -5]]},
      )" + slab("water", "water", 1.0f, 7.0f) + R"(,
      )" + slab("glass", "glass", 3.0f, 4.0f) + R"(
    ]
  })",
                        "slabs.json", ".");
}

Rgb centre(const Scene& scene, const std::string& technique) {
  const Image im = renderWith(scene, technique, "bvh", {}, renderSettings(9, 9, 1, 1)).image;
  return im.at(4, 4);
}

TEST(Numerics_AbsorbingShadows, ShadowThroughNestedSlabsIsDarkenedByBeerLambert) {
  const std::string clearWater = R"({"bsdf": "dielectric", "ior": 1.33})";
  const std::string clearGlass = R"({"bsdf": "dielectric", "ior": 1.5})";
  const std::string water = R"({"bsdf": "dielectric", "ior": 1.33, "absorption": [0.1, 0.05, 0.02]})";
  const std::string glass = R"({"transmission": [1, 1, 1], "ior": 1.5, "absorption": [0.5, 1, 2]})";
  // Water from y = 1 to 7 with glass from 3 to 4 inside: 5 units of water and 1 of glass on the way up.
  const Vec3 expected = glm::exp(-(5.0f * Vec3(0.1f, 0.05f, 0.02f) + 1.0f * Vec3(0.5f, 1.0f, 2.0f)));
  for (const char* technique : {"raycast", "whitted"}) {
    const Rgb clear = centre(slabScene(clearWater, clearGlass), technique);
    const Rgb absorbed = centre(slabScene(water, glass), technique);
    ASSERT_GT(clear.r, 0.5f) << technique << ": the floor is lit through clear slabs";
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(absorbed[c] / clear[c], expected[c], 1e-3f * expected[c]) << technique;
    // Only water: the glass slab absorbs nothing.
    const Rgb onlyWater = centre(slabScene(water, clearGlass), technique);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(onlyWater[c] / clear[c], std::exp(-5.0f * Vec3(0.1f, 0.05f, 0.02f)[c]), 1e-3f) << technique;
  }
}

TEST(Numerics_AbsorbingShadows, OpaqueShadowsBlockTheLight) {
  const Scene scene = slabScene(R"({"bsdf": "dielectric", "ior": 1.33})", R"({"bsdf": "dielectric", "ior": 1.5})");
  for (const char* technique : {"raycast", "whitted"}) {
    const Image im = renderWith(scene, technique, "bvh", {{"shadows", "opaque"}}, renderSettings(9, 9, 1, 1)).image;
    EXPECT_EQ(im.at(4, 4), Rgb(0.0f)) << technique;
  }
}

}  // namespace
}  // namespace ll
