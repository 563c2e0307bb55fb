// The sky as a light (scene/environment.h): its sampler draws directions
// with the density it claims (chi-square), and the path tracer's three
// strategies converge to the analytic answer under a constant sky and to
// one another under an HDR sky with a small bright sun.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/rng.h"
#include "metrics/chi_square.h"
#include "render_support.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

using testing_support::renderSettings;
using testing_support::renderWith;

const std::string kSky = std::string(LIGHTLAB_DATA_DIR) + "/skies/sunny_sky.hdr";

Environment sunnySky(float rotationDeg) {
  return Environment(std::make_shared<Image>(loadImage(kSky)), 1.0f, rotationDeg);
}

// One chi-square cell per pixel: the test's pole is the sky's +y and its azimuth the image's columns
// (w' = (d.z, -d.x, d.y) turns image column u into the test's phi = 2 pi u), so each cell's density is
// smooth and its integral exact; the pixel-to-pixel jumps (the sun's edge) fall on cell borders.
TEST(Numerics_SkyLight, ImageSamplingMatchesItsPdfByChiSquare) {
  for (float rotation : {0.0f, 180.0f}) {
    const Environment sky = sunnySky(rotation);
    Rng rng(1, 0);
    ChiSquareSettings st;
    st.thetaBins = 128;
    st.phiBins = 256;
    st.samples = 1000000;
    const ChiSquareResult r = chiSquareTest(
        [&]() -> std::optional<Vec3> {
          const Vec3 d = sky.sample(rng.uniform2()).dir;
          return Vec3(d.z, -d.x, d.y);
        },
        [&](const Vec3& w) { return static_cast<double>(sky.pdf(Vec3(-w.y, w.z, w.x))); }, st);
    EXPECT_TRUE(r.passed) << "rotation " << rotation << ": " << r.summary();
    EXPECT_NEAR(r.pdfIntegral, 1.0, 1e-4);
  }
}

TEST(Numerics_SkyLight, SamplesCarryTheRadianceOfTheirDirection) {
  const Environment sky = sunnySky(30.0f);
  Rng rng(2, 0);
  double sunShare = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const Environment::Sample s = sky.sample(rng.uniform2());
    EXPECT_NEAR(glm::length(s.dir), 1.0f, 1e-5f);
    EXPECT_EQ(s.radiance, sky.radiance(s.dir));
    EXPECT_NEAR(s.pdf, sky.pdf(s.dir), 1e-4f * s.pdf);
    if (maxComponent(s.radiance) > 100.0f) sunShare += 1e-3;
  }
  // The sun is 0.05 % of the sphere but most of the luminance: importance sampling finds it.
  EXPECT_GT(sunShare, 0.5);
}

// A white diffuse sphere (albedo 0.5) alone under a constant sky of radiance 1: every visible point sees the
// whole sky above it and nothing else, so it shows 0.5 exactly -- with each strategy.
TEST(Numerics_SkyLight, ConstantSkyLightsADiffuseSphereToItsAlbedo) {
  const Scene scene = parseJsonScene(R"({
    "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 20, "width": 16, "height": 16},
    "background": [1, 1, 1],
    "materials": {"grey": {"bsdf": "lambert", "kd": [0.5, 0.5, 0.5]}},
    "objects": [{"type": "sphere", "material": "grey", "center": [0, 0, 0], "radius": 1}]
  })",
                                     "sky.json", ".");
  ASSERT_TRUE(scene.effects.has(Effect::SkyLight));
  for (const char* strategy : {"mis", "light", "bsdf"}) {
    const Image im = renderWith(scene, "path", "bvh", {{"strategy", strategy}}, renderSettings(16, 16, 64, 5)).image;
    double sum = 0.0, sum2 = 0.0;
    for (const Rgb& p : im.pixels()) {
      sum += static_cast<double>(p.g);
      sum2 += static_cast<double>(p.g) * static_cast<double>(p.g);
    }
    const double n = static_cast<double>(im.pixels().size()), mean = sum / n;
    const double se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
    EXPECT_NEAR(mean, 0.5, 4.5 * se + 1e-3) << strategy << ", standard error " << se;
  }
}

// A diffuse floor under the sunny sky: its radiance is (kd / pi) E with E = integral of L cos over the
// upper hemisphere, taken here from the image itself.
TEST(Numerics_SkyLight, HdrSkyLightsAFloorByItsIrradiance) {
  const Environment sky = sunnySky(0.0f);
  double irradiance = 0.0;  // by the midpoint rule over the upper hemisphere
  constexpr int kTheta = 1024, kPhi = 2048;
  for (int i = 0; i < kTheta; ++i) {
    const double theta = (i + 0.5) * (kPiD / 2) / kTheta;
    for (int j = 0; j < kPhi; ++j) {
      const double phi = (j + 0.5) * 2.0 * kPiD / kPhi;
      const Vec3 w(static_cast<float>(std::sin(theta) * std::cos(phi)), static_cast<float>(std::cos(theta)),
                   static_cast<float>(std::sin(theta) * std::sin(phi)));
      irradiance += static_cast<double>(luminance(sky.radiance(w))) * std::cos(theta) * std::sin(theta);
    }
  }
  irradiance *= (kPiD / 2 / kTheta) * (2.0 * kPiD / kPhi);
  const std::string dir = std::string(LIGHTLAB_DATA_DIR) + "/scenes";
  const Scene scene = parseJsonScene(R"({
    "camera": {"eye": [0, 1, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_y_deg": 10, "width": 8, "height": 8},
    "background": {"image": "../skies/sunny_sky.hdr"},
    "materials": {"grey": {"bsdf": "lambert", "kd": [0.5, 0.5, 0.5]}},
    "objects": [{"type": "quad", "material": "grey", "vertices": [[-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1]]}]
  })",
                                     dir + "/floor_under_sky.json", dir);
  const double expected = 0.5 / kPiD * irradiance;
  for (const char* strategy : {"mis", "light"}) {
    const Image im = renderWith(scene, "path", "bvh", {{"strategy", strategy}, {"max_depth", "1"}},
                                renderSettings(8, 8, 256, 9))
                         .image;
    double sum = 0.0;
    for (const Rgb& p : im.pixels()) sum += static_cast<double>(luminance(p));
    EXPECT_NEAR(sum / static_cast<double>(im.pixels().size()), expected, 0.01 * expected) << strategy;
  }
}

TEST(Numerics_SkyLight, AMissingSkyImageIsOneLineNamingIt) {
  try {
    (void)parseJsonScene(R"({"camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 20,
      "width": 8, "height": 8}, "background": {"image": "nowhere.hdr"}, "materials": {}, "objects": []})",
                         "sky.json", "/tmp");
    FAIL() << "no error";
  } catch (const UserError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("sky.json:"), std::string::npos) << what;
    EXPECT_NE(what.find("sky image not found: /tmp/nowhere.hdr"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace ll
