#include "metrics/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "core/error.h"

namespace ll {
namespace {

// A textured test image in [0,1]: smooth gradients plus stripes, so SSIM has
// structure to compare.
Image patternImage(int w, int h) {
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float fx = static_cast<float>(x), fy = static_cast<float>(y);
      const float v = 0.5f + 0.4f * std::sin(0.45f * fx) * std::cos(0.3f * fy);
      image.at(x, y) = Rgb(v, 0.8f * v + 0.1f, fx / static_cast<float>(w));
    }
  return image;
}

TEST(ImageMetrics, IdenticalImages) {
  const Image img = patternImage(40, 30);
  const ImageError e = compareImages(img, img);
  EXPECT_EQ(e.rmse, 0.0);
  EXPECT_EQ(e.relmse, 0.0);
  EXPECT_EQ(e.maxAbs, 0.0);
  EXPECT_NEAR(e.ssim, 1.0, 1e-9);
  EXPECT_TRUE(std::isinf(e.psnr) && e.psnr > 0.0);
  EXPECT_DOUBLE_EQ(e.meanA, e.meanB);
}

TEST(ImageMetrics, RmseOfConstantOffset) {
  const float d = 0.1f;
  const Image a(16, 12, Rgb(0.25f + d)), b(16, 12, Rgb(0.25f));
  const ImageError e = compareImages(a, b);
  EXPECT_NEAR(e.rmse, 0.1, 1e-6);
  EXPECT_NEAR(e.maxAbs, 0.1, 1e-6);
  EXPECT_NEAR(e.psnr, -20.0 * std::log10(0.1), 1e-4);  // 20 dB
  EXPECT_NEAR(e.meanA, 0.35, 1e-6);
  EXPECT_NEAR(e.meanB, 0.25, 1e-6);
}

TEST(ImageMetrics, PsnrOfSmallOffset) {
  const Image a(20, 20, Rgb(0.5f)), b(20, 20, Rgb(0.51f));
  EXPECT_NEAR(compareImages(a, b).psnr, -20.0 * std::log10(0.01), 1e-3);  // 40 dB
}

TEST(ImageMetrics, PsnrClampsToUnitRange) {
  // Both values are above 1: equal after clamping, so the PSNR is infinite,
  // while the RMSE still sees the linear difference.
  const Image a(8, 8, Rgb(5.0f)), b(8, 8, Rgb(2.0f));
  const ImageError e = compareImages(a, b);
  EXPECT_TRUE(std::isinf(e.psnr));
  EXPECT_NEAR(e.rmse, 3.0, 1e-6);
}

TEST(ImageMetrics, RelMseOfConstantPair) {
  // (0.6 - 0.5)^2 / (0.5^2 + 0.01) = 0.01 / 0.26
  const Image a(10, 7, Rgb(0.6f)), b(10, 7, Rgb(0.5f));
  EXPECT_NEAR(compareImages(a, b).relmse, 0.01 / 0.26, 1e-6);
  // The reference is the second argument: swapping changes the value.
  EXPECT_NEAR(compareImages(b, a).relmse, 0.01 / 0.37, 1e-6);
}

TEST(ImageMetrics, SsimOfConstantImagesIsLuminanceTerm) {
  // White vs black: both windows are flat, so SSIM = C1 / (1 + C1) exactly,
  // both with the Gaussian window and on the whole-image fallback.
  const double c1 = 1e-4;
  for (int size : {32, 5}) {
    const Image white(size, size, Rgb(1.0f)), black(size, size, Rgb(0.0f));
    EXPECT_NEAR(compareImages(white, black).ssim, c1 / (1.0 + c1), 1e-6) << size;
  }
}

TEST(ImageMetrics, SsimDropsWithNoiseAndMoreWithInversion) {
  const Image img = patternImage(64, 48);
  Image noisy = img;
  std::mt19937 rng(7);
  std::normal_distribution<float> noise(0.0f, 0.05f);
  for (Rgb& p : noisy.pixels()) p = glm::clamp(p + Rgb(noise(rng), noise(rng), noise(rng)), 0.0f, 1.0f);
  Image inverted = img;  // contrast-inverted in display (sRGB) space
  for (Rgb& p : inverted.pixels())
    for (int c = 0; c < 3; ++c) p[c] = srgbToLinear(1.0f - linearToSrgb(p[c]));

  const double noisySsim = compareImages(noisy, img).ssim;
  const double invertedSsim = compareImages(inverted, img).ssim;
  EXPECT_LT(noisySsim, 0.99);
  EXPECT_GT(noisySsim, 0.3);
  EXPECT_LT(invertedSsim, noisySsim - 0.5);
  EXPECT_LT(invertedSsim, 0.0);  // anti-correlated structure
}

TEST(ImageMetrics, SsimOnImagesSmallerThanWindow) {
  const Image img = patternImage(30, 6);  // 6 rows < 11: one whole-image window
  EXPECT_NEAR(compareImages(img, img).ssim, 1.0, 1e-9);
  Image brighter = img;
  for (Rgb& p : brighter.pixels()) p = glm::min(p * 1.5f, Rgb(1.0f));
  const double s = compareImages(brighter, img).ssim;
  EXPECT_LT(s, 1.0);
  EXPECT_GT(s, 0.5);
}

TEST(ImageMetrics, SizeMismatchThrows) {
  const Image a(10, 10), b(10, 11);
  EXPECT_THROW(compareImages(a, b), UserError);
  try {
    compareImages(a, b);
  } catch (const UserError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("10x10"), std::string::npos) << msg;
    EXPECT_NE(msg.find("10x11"), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
  EXPECT_THROW(differenceHeatmap(a, b, DiffMode::Absolute), UserError);
  EXPECT_THROW(compareImages(Image(), Image()), UserError);
}

TEST(ImageMetrics, MetricValueByName) {
  ImageError e;
  e.rmse = 1.0;
  e.relmse = 2.0;
  e.psnr = 3.0;
  e.ssim = 4.0;
  e.maxAbs = 5.0;
  const std::vector<std::string> names = metricNames();
  ASSERT_EQ(names.size(), 5u);
  for (size_t i = 0; i < names.size(); ++i)
    EXPECT_EQ(metricValue(e, names[i]), static_cast<double>(i + 1)) << names[i];
}

TEST(ImageMetrics, MetricValueUnknownNameListsAllowed) {
  try {
    metricValue(ImageError{}, "mse");
    FAIL() << "expected UserError";
  } catch (const UserError& err) {
    EXPECT_STREQ(err.what(), "unknown metric 'mse' (allowed: rmse, relmse, psnr, ssim, maxabs)");
  }
}

TEST(ImageMetrics, ColormapIsDarkToBrightInLinearRgb) {
  const Rgb lo = errorColormap(0.0f), hi = errorColormap(1.0f);
  // Published sRGB end points of inferno, decoded to linear.
  EXPECT_NEAR(lo.b, srgbToLinear(0.013866f), 1e-6f);
  EXPECT_NEAR(hi.r, srgbToLinear(0.988362f), 1e-6f);
  EXPECT_NEAR(hi.g, srgbToLinear(0.998364f), 1e-6f);
  EXPECT_LT(luminance(lo), 0.01f);
  EXPECT_GT(luminance(hi), 0.8f);
  float previous = -1.0f;  // inferno's lightness increases monotonically
  for (int i = 0; i <= 100; ++i) {
    const float l = luminance(errorColormap(static_cast<float>(i) / 100.0f));
    EXPECT_GT(l, previous) << i;
    previous = l;
  }
  EXPECT_EQ(errorColormap(-3.0f), lo);
  EXPECT_EQ(errorColormap(7.0f), hi);
}

TEST(ImageMetrics, HeatmapOfIdenticalImagesIsZeroColour) {
  const Image img = patternImage(20, 15);
  for (DiffMode mode : {DiffMode::Absolute, DiffMode::Relative}) {
    float used = -1.0f;
    const Image heat = differenceHeatmap(img, img, mode, 0.0f, &used);
    ASSERT_EQ(heat.width(), 20);
    ASSERT_EQ(heat.height(), 15);
    EXPECT_GT(used, 0.0f);  // a usable scale even though every error is 0
    for (const Rgb& p : heat.pixels()) ASSERT_EQ(p, errorColormap(0.0f));
  }
}

TEST(ImageMetrics, HeatmapUsedMaxIsThe99thPercentile) {
  // 1000 pixels with errors 0.000, 0.001, ..., 0.999 in shuffled order: the
  // nearest-rank 99th percentile is the 990th smallest, 0.989.
  std::vector<int> order(1000);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(3));
  Image a(40, 25), b(40, 25);
  for (size_t i = 0; i < order.size(); ++i) a.pixels()[i] = Rgb(static_cast<float>(order[i]) / 1000.0f);
  float used = 0.0f;
  const Image heat = differenceHeatmap(a, b, DiffMode::Absolute, 0.0f, &used);
  EXPECT_NEAR(used, 0.989f, 1e-6f);
  // Errors at or above the scale are clamped to the brightest colour.
  for (size_t i = 0; i < order.size(); ++i) {
    if (order[i] >= 989) {
      EXPECT_EQ(heat.pixels()[i], errorColormap(1.0f)) << order[i];
    }
  }
}

TEST(ImageMetrics, HeatmapIgnoresSingleOutlier) {
  Image a(10, 10, Rgb(0.1f)), b(10, 10, Rgb(0.0f));
  a.at(3, 4) = Rgb(100.0f);  // one firefly in 100 pixels
  float used = 0.0f;
  const Image heat = differenceHeatmap(a, b, DiffMode::Absolute, -1.0f, &used);
  EXPECT_NEAR(used, 0.1f, 1e-6f);
  EXPECT_EQ(heat.at(0, 0), errorColormap(1.0f));
  EXPECT_EQ(heat.at(3, 4), errorColormap(1.0f));
  EXPECT_NO_THROW(differenceHeatmap(a, b, DiffMode::Absolute));  // usedMax may be null
}

TEST(ImageMetrics, HeatmapWithExplicitScale) {
  Image a(3, 1), b(3, 1, Rgb(1.0f));
  a.at(0, 0) = Rgb(1.0f);  // error 0
  a.at(1, 0) = Rgb(1.5f);  // error 0.5 = half the scale
  a.at(2, 0) = Rgb(3.0f);  // error 2 > scale
  float used = 0.0f;
  const Image heat = differenceHeatmap(a, b, DiffMode::Absolute, 1.0f, &used);
  EXPECT_EQ(used, 1.0f);
  EXPECT_EQ(heat.at(0, 0), errorColormap(0.0f));
  EXPECT_EQ(heat.at(1, 0), errorColormap(0.5f));
  EXPECT_EQ(heat.at(2, 0), errorColormap(1.0f));

  // Relative: 0.5 / (1 + 0.01) of a scale of 1.
  const Image rel = differenceHeatmap(a, b, DiffMode::Relative, 1.0f);
  const Rgb expected = errorColormap(0.5f / 1.01f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(rel.at(1, 0)[c], expected[c], 1e-6f);
}

TEST(ImageMetrics, LegendAppendsGradientStripWithTicks) {
  const Image heat(33, 10, Rgb(0.25f));
  const Image out = withLegend(heat, 0.5f);
  ASSERT_EQ(out.width(), 33);
  ASSERT_EQ(out.height(), 10 + kLegendHeight);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 33; ++x) ASSERT_EQ(out.at(x, y), Rgb(0.25f));
  // Somewhere in the strip the bar runs from colormap(0) to colormap(1).
  bool foundBar = false;
  for (int y = 10; y < out.height(); ++y)
    if (out.at(0, y) == errorColormap(0.0f) && out.at(32, y) == errorColormap(1.0f) &&
        out.at(16, y) == errorColormap(0.5f))
      foundBar = true;
  EXPECT_TRUE(foundBar);
  // Tick marks (white) at 0, 0.5 and 1 of the scale, nowhere else in that row.
  bool foundTicks = false;
  for (int y = 10; y < out.height(); ++y) {
    int white = 0;
    for (int x = 0; x < 33; ++x) white += out.at(x, y) == Rgb(1.0f) ? 1 : 0;
    if (white == 3 && out.at(0, y) == Rgb(1.0f) && out.at(16, y) == Rgb(1.0f) &&
        out.at(32, y) == Rgb(1.0f))
      foundTicks = true;
  }
  EXPECT_TRUE(foundTicks);

  EXPECT_THROW(withLegend(Image(), 1.0f), UserError);
  EXPECT_THROW(withLegend(heat, 0.0f), UserError);
  EXPECT_THROW(withLegend(heat, std::numeric_limits<float>::quiet_NaN()), UserError);
}

}  // namespace
}  // namespace ll
