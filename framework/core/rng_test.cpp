#include "core/rng.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "render/technique.h"

namespace ll {
namespace {

TEST(Rng, Pcg32MatchesReferenceImplementation) {
  // pcg32-demo (O'Neill): pcg32_srandom(42, 54) then pcg32_random() six times.
  Rng rng(42u, 54u);
  const std::array<uint32_t, 6> expected = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u,
                                            0x83d2f293u, 0xbfa4784bu, 0xcbed606eu};
  for (uint32_t e : expected) EXPECT_EQ(rng.nextU32(), e);
}

TEST(Rng, Mix64IsSplitMix64) {
  // mix64(z) is SplitMix64's output for state z (values from the reference algorithm).
  static_assert(mix64(0) == 0xe220a8397b1dcdafull);
  EXPECT_EQ(mix64(1), 0x910a2dec89025cc1ull);
  EXPECT_NE(mix64(0), mix64(1));
}

TEST(Rng, ForPixelIsDeterministic) {
  Rng a = Rng::forPixel(7, 1234, 3);
  Rng b = Rng::forPixel(7, 1234, 3);
  Rng other = Rng::forPixel(7, 999, 3);  // interleaving another stream changes nothing
  for (int i = 0; i < 1000; ++i) {
    (void)other.nextU32();
    ASSERT_EQ(a.nextU32(), b.nextU32()) << i;
  }
  Rng c = Rng::forPixel(7, 1234, 3);
  Rng d = Rng::forPixel(7, 1234, 3);
  for (int i = 0; i < 100; ++i) ASSERT_EQ(c.uniform(), d.uniform());
}

// The first 8 outputs of a stream, as a fingerprint.
std::array<uint32_t, 8> head(Rng rng) {
  std::array<uint32_t, 8> out{};
  for (uint32_t& v : out) v = rng.nextU32();
  return out;
}

TEST(Rng, DifferentPixelSampleOrSeedGiveDifferentStreams) {
  const auto base = head(Rng::forPixel(0, 0, 0));
  EXPECT_NE(head(Rng::forPixel(0, 1, 0)), base);
  EXPECT_NE(head(Rng::forPixel(0, 0, 1)), base);
  EXPECT_NE(head(Rng::forPixel(1, 0, 0)), base);
  // Neighbouring pixels and samples of a 64x64, 4 spp image: all streams distinct.
  std::set<std::array<uint32_t, 8>> seen;
  for (uint64_t pixel = 0; pixel < 64 * 64; ++pixel)
    for (uint64_t sample = 0; sample < 4; ++sample) seen.insert(head(Rng::forPixel(5, pixel, sample)));
  EXPECT_EQ(seen.size(), 64u * 64u * 4u);
  // Swapping pixel and sample index must not give the same stream.
  EXPECT_NE(head(Rng::forPixel(0, 2, 3)), head(Rng::forPixel(0, 3, 2)));
}

TEST(Rng, UniformIsInUnitIntervalWithRightMoments) {
  Rng rng = Rng::forPixel(11, 42, 0);
  constexpr int kN = 100000;
  double sum = 0.0, sumSq = 0.0;
  float lo = 1.0f, hi = 0.0f;
  std::array<int, 10> bins{};
  for (int i = 0; i < kN; ++i) {
    const float u = rng.uniform();
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
    lo = std::min(lo, u);
    hi = std::max(hi, u);
    sum += static_cast<double>(u);
    sumSq += static_cast<double>(u) * static_cast<double>(u);
    ++bins[static_cast<size_t>(u * 10.0f)];
  }
  const double mean = sum / kN;
  const double variance = sumSq / kN - mean * mean;
  // Uniform[0,1): mean 1/2 with standard error sqrt(1/12 / N); allow 5 sigma.
  const double se = std::sqrt(1.0 / 12.0 / kN);
  EXPECT_NEAR(mean, 0.5, 5.0 * se);
  EXPECT_NEAR(variance, 1.0 / 12.0, 0.002);  // sd of the variance estimate ~ 2.4e-4
  EXPECT_LT(lo, 1e-3f);
  EXPECT_GT(hi, 1.0f - 1e-3f);
  // Pearson chi-square over 10 bins, 9 degrees of freedom: 40 is p ~ 7e-6.
  double chi2 = 0.0;
  for (int b : bins) chi2 += (b - kN / 10.0) * (b - kN / 10.0) / (kN / 10.0);
  EXPECT_LT(chi2, 40.0);
}

TEST(Rng, UniformUsesTopTwentyFourBits) {
  // uniform() = (nextU32() >> 8) * 2^-24, so it is exact in float and never 1.
  Rng a(3, 4), b(3, 4);
  for (int i = 0; i < 1000; ++i) {
    const uint32_t bits = a.nextU32();
    const float u = b.uniform();
    ASSERT_EQ(u, static_cast<float>(bits >> 8) / 16777216.0f);
  }
  EXPECT_LT(static_cast<float>(0xffffffu) * 0x1p-24f, 1.0f);
}

TEST(Rng, Uniform2TakesConsecutiveDraws) {
  Rng a(9, 1), b(9, 1);
  const Vec2 p = a.uniform2();
  const float x = b.uniform();
  const float y = b.uniform();
  EXPECT_EQ(p.x, x);
  EXPECT_EQ(p.y, y);
}

TEST(StratifiedOffset, SingleSampleIsPixelCentre) {
  Rng rng(1, 2);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(stratifiedOffset(0, 1, rng), Vec2(0.5f, 0.5f));
  EXPECT_EQ(stratifiedOffset(0, 0, rng), Vec2(0.5f, 0.5f));
}

TEST(StratifiedOffset, SixteenSamplesFillEachStratumOnce) {
  for (uint64_t pixel = 0; pixel < 50; ++pixel) {
    std::array<int, 16> count{};
    for (int i = 0; i < 16; ++i) {
      Rng rng = Rng::forPixel(0, pixel, static_cast<uint64_t>(i));
      const Vec2 o = stratifiedOffset(i, 16, rng);
      ASSERT_GE(o.x, 0.0f);
      ASSERT_LT(o.x, 1.0f);
      ASSERT_GE(o.y, 0.0f);
      ASSERT_LT(o.y, 1.0f);
      const int cx = static_cast<int>(o.x * 4.0f), cy = static_cast<int>(o.y * 4.0f);
      ++count[static_cast<size_t>(cy * 4 + cx)];
    }
    for (int c = 0; c < 16; ++c) ASSERT_EQ(count[static_cast<size_t>(c)], 1) << "stratum " << c << " pixel " << pixel;
  }
}

TEST(StratifiedOffset, NonSquareCountsTileThePixelWithColumns) {
  // 5 samples: 5 columns, one sample in each (a 3x3 grid would leave 4 of its 9 cells, and so part of
  // the pixel, unsampled: a biased average).
  std::set<int> columns;
  Rng rng(4, 4);
  for (int i = 0; i < 5; ++i) {
    const Vec2 o = stratifiedOffset(i, 5, rng);
    ASSERT_GE(minComponent(Vec3(o, 0.5f)), 0.0f);
    ASSERT_LT(maxComponent(Vec3(o, 0.5f)), 1.0f);
    columns.insert(static_cast<int>(o.x * 5.0f));
  }
  EXPECT_EQ(columns.size(), 5u);
  // Unbiased: over many pixels the mean offset of 8 samples is the pixel centre in both axes.
  Vec2 sum(0.0f);
  for (uint64_t p = 0; p < 20000; ++p) {
    Rng r(p, 1);
    for (int i = 0; i < 8; ++i) sum += stratifiedOffset(i, 8, r);
  }
  EXPECT_NEAR(sum.x / 160000.0f, 0.5f, 3e-3f);
  EXPECT_NEAR(sum.y / 160000.0f, 0.5f, 3e-3f);
  // The jitter inside a stratum comes from the rng: the same rng state gives the same offset.
  Rng r1(8, 8), r2(8, 8);
  EXPECT_EQ(stratifiedOffset(3, 16, r1), stratifiedOffset(3, 16, r2));
}

TEST(StratifiedOffset, JitterCoversTheStratum) {
  // Many draws for one stratum spread over the whole cell, not a fixed point.
  Rng rng(123, 0);
  Vec2 lo(1.0f), hi(0.0f);
  for (int k = 0; k < 2000; ++k) {
    const Vec2 o = stratifiedOffset(5, 16, rng);  // cell (1, 1): [0.25, 0.5)^2
    ASSERT_GE(o.x, 0.25f);
    ASSERT_LT(o.x, 0.5f);
    ASSERT_GE(o.y, 0.25f);
    ASSERT_LT(o.y, 0.5f);
    lo = glm::min(lo, o);
    hi = glm::max(hi, o);
  }
  EXPECT_LT(lo.x, 0.26f);
  EXPECT_LT(lo.y, 0.26f);
  EXPECT_GT(hi.x, 0.49f);
  EXPECT_GT(hi.y, 0.49f);
}

}  // namespace
}  // namespace ll
