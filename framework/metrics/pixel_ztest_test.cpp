#include "metrics/pixel_ztest.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/rng.h"

namespace ll {
namespace {

// Normal samples by Box-Muller from the framework's random stream.
float gaussian(Rng& rng) {
  const float u1 = std::max(rng.uniform(), 1e-7f), u2 = rng.uniform();
  return std::sqrt(-2.0f * std::log(u1)) * std::cos(6.2831853f * u2);
}

Image noisy(const Image& mean, float sigma, uint64_t seed, float bias = 0.0f) {
  Image out(mean.width(), mean.height());
  Rng rng(seed, 0);
  for (size_t i = 0; i < out.pixelCount(); ++i)
    for (int c = 0; c < 3; ++c) out.pixels()[i][c] = mean.pixels()[i][c] + bias + sigma * gaussian(rng);
  return out;
}

TEST(PixelZTest, CorrectEstimatesPassAtTheFamilyWiseLevel) {
  const Image mean(64, 64, Rgb(0.5f)), variance(64, 64, Rgb(0.01f));
  int failures = 0;
  for (uint64_t seed = 1; seed <= 200; ++seed) failures += pixelZTest(noisy(mean, 0.1f, seed), mean, variance).passed ? 0 : 1;
  // alpha = 0.01 for the whole image: about 2 of 200 correct images fail; 8 would be very unlikely (p < 1e-3).
  EXPECT_LE(failures, 8);
}

TEST(PixelZTest, ABiasOfAFewSigmaIsCaught) {
  const Image mean(64, 64, Rgb(0.5f)), variance(64, 64, Rgb(0.01f));
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const ZTestResult r = pixelZTest(noisy(mean, 0.1f, seed, 0.0f), mean, variance);
    Image wrong = noisy(mean, 0.1f, seed);
    for (int y = 20; y < 30; ++y)
      for (int x = 20; x < 30; ++x) wrong.at(x, y) += Rgb(0.7f);  // a 7-sigma bias in a 10x10 patch
    const ZTestResult w = pixelZTest(wrong, mean, variance);
    EXPECT_FALSE(w.passed) << seed;
    EXPECT_GE(w.worstX, 20);
    EXPECT_LT(w.worstX, 30);
    EXPECT_LT(w.minPValue, r.minPValue);
  }
}

TEST(PixelZTest, SidakCorrectionAndNonFinitePixels) {
  Image mean(10, 10, Rgb(1.0f)), variance(10, 10, Rgb(0.0f));
  ZTestResult r = pixelZTest(mean, mean, variance);
  EXPECT_TRUE(r.passed);
  EXPECT_EQ(r.tests, 300u);
  EXPECT_NEAR(r.correctedAlpha, 1.0 - std::pow(0.99, 1.0 / 300.0), 1e-12);
  Image bad = mean;
  bad.at(3, 4) = Rgb(std::nanf(""), 1.0f, 1.0f);
  r = pixelZTest(bad, mean, variance);
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.nonFinite, 1u);
  // Deterministic pixels: rounding-level differences pass thanks to the floor, real ones fail.
  Image close = mean;
  close.at(1, 1) = Rgb(1.0f + 1e-6f);
  EXPECT_TRUE(pixelZTest(close, mean, variance).passed);
  close.at(1, 1) = Rgb(1.1f);
  EXPECT_FALSE(pixelZTest(close, mean, variance).passed);
  EXPECT_THROW(pixelZTest(Image(2, 2), mean, variance), UserError);
}

TEST(PixelZTest, MaxRejectedToleratesAFewOutliersButNotABiasOrANaN) {
  const Image mean(32, 32, Rgb(0.5f)), variance(32, 32, Rgb(0.01f));
  ZTestSettings lenient;
  lenient.maxRejected = 6;
  Image outliers = noisy(mean, 0.1f, 3);
  outliers.at(5, 5) = Rgb(2.0f);  // one pixel 15 sigma off in every channel: 3 rejections
  EXPECT_FALSE(pixelZTest(outliers, mean, variance).passed);
  EXPECT_TRUE(pixelZTest(outliers, mean, variance, lenient).passed);
  Image biased = noisy(mean, 0.1f, 3, 0.6f);  // 6 sigma everywhere
  const ZTestResult b = pixelZTest(biased, mean, variance, lenient);
  EXPECT_FALSE(b.passed);
  EXPECT_GT(b.rejected, 100u);
  Image nan = noisy(mean, 0.1f, 3);
  nan.at(1, 2).g = std::nanf("");
  EXPECT_FALSE(pixelZTest(nan, mean, variance, lenient).passed);
}

}  // namespace
}  // namespace ll
