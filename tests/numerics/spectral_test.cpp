// Spectral path tracing (assignments/a6_path_tracing/spectral.h): a grey
// world renders the same spectrally and in RGB (the furnace's analytic
// answer), the measured Cornell box stays within a few per cent of its RGB
// projection, and a dispersive prism splits white light into colours that
// RGB rendering cannot make.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/params.h"
#include "modules/registry.h"
#include "render_support.h"
#include "scene/scene_loader.h"
#include "spectral.h"

namespace ll {
namespace {

using testing_support::renderSettings;
using testing_support::renderWith;

#define SKIP_WITHOUT_SOLUTION() \
  if (!LIGHTLAB_SOLUTION) GTEST_SKIP() << "renders with the A6 solution"

const std::string kScenes = std::string(LIGHTLAB_DATA_DIR) + "/scenes/";

TEST(Numerics_Spectral, HeroWavelengthsAreSpreadAThirdOfTheRangeApart) {
  for (float u : {0.0f, 0.3f, 0.9999f}) {
    const a6::Wavelengths w = a6::Wavelengths::sample(u);
    for (float nm : w.nm) {
      EXPECT_GE(nm, a6::kMinNm);
      EXPECT_LT(nm, a6::kMaxNm);
    }
    const float third = (a6::kMaxNm - a6::kMinNm) / 3.0f;
    EXPECT_NEAR(std::fmod(w.nm[1] - w.nm[0] + 3.0f * third, 3.0f * third), third, 1e-2f);
    EXPECT_NEAR(std::fmod(w.nm[2] - w.nm[0] + 3.0f * third, 3.0f * third), 2.0f * third, 1e-2f);
  }
}

TEST(Numerics_Spectral, AnUpsampledGreyProjectsBackToItself) {
  const a6::SpectralContext spectral;
  // The projection of the three-wavelength estimate, averaged over many hero wavelengths.
  for (float grey : {0.2f, 0.5f, 0.9f}) {
    Rgb sum(0.0f);
    constexpr int kN = 4700;
    for (int i = 0; i < kN; ++i) {
      const a6::Wavelengths w = a6::Wavelengths::sample((static_cast<float>(i) + 0.5f) / kN);
      sum += spectral.toRgb(spectral.upsample(Rgb(grey), w), w);
    }
    const Rgb mean = sum / static_cast<float>(kN);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], grey, 2e-3f * grey) << "grey " << grey << " channel " << c;
  }
}

// The white furnace (every wall emits 1 and reflects 0.8): 1 / (1 - 0.8) = 5 in every pixel, spectral or not.
TEST(Numerics_Spectral, GreyFurnaceConvergesToItsAnalyticAnswer) {
  SKIP_WITHOUT_SOLUTION();
  const Scene scene = loadScene(kScenes + "tests/furnace.json");
  const Image im = renderWith(scene, "path", "bvh", {{"spectral", "true"}, {"max_depth", "256"}},
                              renderSettings(16, 16, 64, 3))
                       .image;
  double sum = 0.0, sum2 = 0.0;
  for (const Rgb& p : im.pixels()) {
    const auto v = static_cast<double>(luminance(p));
    sum += v;
    sum2 += v * v;
  }
  const double n = static_cast<double>(im.pixels().size()), mean = sum / n;
  const double se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
  EXPECT_NEAR(mean, 5.0, 4.5 * se + 0.01) << "standard error " << se;
  EXPECT_LT(se, 0.1);
}

// Measured spectra against their RGB projection: the products of spectra differ from the products of
// their projections, but little for these broad reflectances (the study `spectral` shows where).
TEST(Numerics_Spectral, MeasuredCornellBoxStaysCloseToItsRgbProjection) {
  SKIP_WITHOUT_SOLUTION();
  const Scene scene = loadScene(kScenes + "cornell_box_spectral.json");
  ASSERT_TRUE(scene.materials.at(0).kdSpectrum);
  const auto mean = [&](const char* spectral) {
    const Image im =
        renderWith(scene, "path", "bvh", {{"spectral", spectral}}, renderSettings(32, 32, 256, 4)).image;
    Rgb s(0.0f);
    for (const Rgb& p : im.pixels()) s += p;
    return s / static_cast<float>(im.pixels().size());
  };
  const Rgb spectral = mean("true"), rgb = mean("false");
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(spectral[c], rgb[c], 0.04f * rgb[c]) << "channel " << c;
}

// Through the prism, RGB shows a white strip (every lit pixel grey); spectral rendering spreads it into
// a spectrum: some pixels clearly red, some clearly blue.
TEST(Numerics_Spectral, PrismDispersesWhiteLightOnlySpectrally) {
  SKIP_WITHOUT_SOLUTION();
  const Scene scene = loadScene(kScenes + "prism.json");
  const auto colourfulPixels = [&](const char* spectral, int& reddish, int& bluish, int& lit) {
    const Image im =
        renderWith(scene, "path", "bvh", {{"spectral", spectral}}, renderSettings(48, 48, 64, 5)).image;
    reddish = bluish = lit = 0;
    for (const Rgb& p : im.pixels()) {
      if (luminance(p) < 0.05f) continue;
      ++lit;
      if (p.r > 3.0f * std::max(p.b, 0.01f) && p.r > p.g) ++reddish;
      if (p.b > 3.0f * std::max(p.r, 0.01f) && p.b > p.g) ++bluish;
    }
  };
  int reddish = 0, bluish = 0, lit = 0;
  colourfulPixels("false", reddish, bluish, lit);
  EXPECT_GT(lit, 20);
  EXPECT_EQ(reddish + bluish, 0) << "RGB has one index: no colours from white light";
  colourfulPixels("true", reddish, bluish, lit);
  EXPECT_GT(reddish, 5);
  EXPECT_GT(bluish, 5);
}

// The prism calls for dispersion; path simulates it only spectrally, and says so (GUI captions, info).
TEST(Numerics_Spectral, PathSimulatesDispersionOnlyWithSpectralTrue) {
  const Scene scene = loadScene(kScenes + "prism.json");
  EXPECT_TRUE(scene.effects.has(Effect::Dispersion));
  EXPECT_FALSE(loadScene(kScenes + "whitted_1980.json").effects.has(Effect::Dispersion));
  const TechniqueInfo& path = findTechnique("path");
  ParamSet values("technique 'path'", path.params);
  EXPECT_FALSE(path.simulatesWith(values).has(Effect::Dispersion));
  values.assign("spectral=true");
  EXPECT_TRUE(path.simulatesWith(values).has(Effect::Dispersion));
  const TechniqueInfo& whitted = findTechnique("whitted");
  EXPECT_FALSE(whitted.simulatesWith(ParamSet("technique 'whitted'", whitted.params)).has(Effect::Dispersion));
}

}  // namespace
}  // namespace ll
