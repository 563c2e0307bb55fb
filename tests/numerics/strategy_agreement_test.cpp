// Light sampling, BSDF sampling and their combination by MIS are three
// estimators of one integral: on a rough copper sphere and a rough glass
// sphere, lit by an area light and a sky, their images converge to the same
// picture. Compared region by region (each sphere, the floor) by the mean of
// independent renders, within 4.5 standard errors of the difference.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render_support.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

using testing_support::renderSettings;
using testing_support::renderWith;

Scene metalAndGlass() {
  const std::string dir = std::string(LIGHTLAB_DATA_DIR) + "/scenes";
  return parseJsonScene(R"({
    "camera": {"eye": [0, 1.2, 4.5], "target": [0, 0.6, 0], "up": [0, 1, 0], "fov_y_deg": 40,
               "width": 32, "height": 24},
    "background": [0.3, 0.35, 0.4],
    "materials": {
      "floor": {"bsdf": "lambert", "kd": [0.5, 0.5, 0.5]},
      "lamp": {"bsdf": "lambert", "emission": [8, 8, 8]},
      "copper": {"bsdf": "conductor", "metal": "copper", "roughness": 0.2},
      "frosted": {"bsdf": "rough-dielectric", "ior": 1.5, "roughness": 0.3}
    },
    "objects": [
      {"type": "quad", "name": "floor", "material": "floor",
       "vertices": [[-5, 0, -5], [-5, 0, 5], [5, 0, 5], [5, 0, -5]]},
      {"type": "quad", "name": "lamp", "material": "lamp",
       "vertices": [[-0.7, 3, -0.7], [0.7, 3, -0.7], [0.7, 3, 0.7], [-0.7, 3, 0.7]]},
      {"type": "sphere", "name": "copper", "material": "copper", "center": [-0.8, 0.6, 0], "radius": 0.6},
      {"type": "sphere", "name": "frosted", "material": "frosted", "center": [0.8, 0.6, 0], "radius": 0.6}
    ]
  })",
                        dir + "/metal_and_glass.json", dir);
}

// Mean luminance of the left third, the right third and the bottom quarter (floor) of each of `renders`
// renders; per region, the mean over renders and its standard error.
struct RegionMeans {
  std::array<double, 3> mean{}, standardError{};
};
RegionMeans regions(const Scene& scene, const char* strategy, int renders) {
  std::array<std::vector<double>, 3> values;
  for (int k = 0; k < renders; ++k) {
    const Image im = renderWith(scene, "path", "bvh", {{"strategy", strategy}},
                                renderSettings(32, 24, 16, 100 + static_cast<uint64_t>(k)))
                         .image;
    std::array<double, 3> sum{};
    std::array<int, 3> count{};
    for (int y = 0; y < im.height(); ++y)
      for (int x = 0; x < im.width(); ++x) {
        const auto v = static_cast<double>(luminance(im.at(x, y)));
        if (x < im.width() / 3 && y < im.height() * 3 / 4) sum[0] += v, ++count[0];
        if (x >= im.width() * 2 / 3 && y < im.height() * 3 / 4) sum[1] += v, ++count[1];
        if (y >= im.height() * 3 / 4) sum[2] += v, ++count[2];
      }
    for (size_t r = 0; r < 3; ++r) values[r].push_back(sum[r] / count[r]);
  }
  RegionMeans m;
  for (size_t r = 0; r < 3; ++r) {
    double s = 0.0, s2 = 0.0;
    for (double v : values[r]) s += v, s2 += v * v;
    const double n = static_cast<double>(renders), mean = s / n;
    m.mean[r] = mean;
    m.standardError[r] = std::sqrt(std::max(0.0, (s2 - n * mean * mean) / (n - 1.0)) / n);
  }
  return m;
}

TEST(Numerics_Strategies, LightBsdfAndMisConvergeToOneImageOnRoughMetalAndGlass) {
  const Scene scene = metalAndGlass();
  ASSERT_TRUE(scene.effects.has(Effect::GlossyReflection));
  constexpr int kRenders = 8;
  const RegionMeans mis = regions(scene, "mis", kRenders);
  const char* names[3] = {"copper sphere", "frosted sphere", "floor"};
  for (const char* strategy : {"light", "bsdf"}) {
    const RegionMeans other = regions(scene, strategy, kRenders);
    for (size_t r = 0; r < 3; ++r) {
      const double se = std::hypot(mis.standardError[r], other.standardError[r]);
      EXPECT_NEAR(other.mean[r], mis.mean[r], 4.5 * se + 1e-4)
          << strategy << " against mis, " << names[r] << ": standard error of the difference " << se;
      EXPECT_LT(se, 0.03 * mis.mean[r]) << strategy << ", " << names[r] << ": the test must resolve 10 %";
    }
  }
}

}  // namespace
}  // namespace ll
