// Deterministic random numbers. Every stream is derived from (seed, pixel,
// sample) by hashing, never from threads or time, so an image is the same for
// any thread count or tile order.
#pragma once

#include <cstdint>

#include "core/math.h"

namespace ll {

// SplitMix64 finaliser: a strong 64-bit mix used to derive stream seeds.
constexpr uint64_t mix64(uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// PCG32 (O'Neill 2014): small state, good statistics, cheap to seed per pixel.
class Rng {
 public:
  Rng(uint64_t seed, uint64_t stream) { reseed(seed, stream); }

  // The stream for one pixel sample: seed, pixel index y*width+x, sample index.
  static Rng forPixel(uint64_t seed, uint64_t pixelIndex, uint64_t sampleIndex) {
    return Rng(mix64(seed ^ mix64(pixelIndex)), mix64(sampleIndex + 0x632be59bd9b4e019ull * seed));
  }

  void reseed(uint64_t seed, uint64_t stream) {
    state_ = 0u;
    inc_ = (stream << 1u) | 1u;
    nextU32();
    state_ += seed;
    nextU32();
  }

  uint32_t nextU32() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const auto xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
  }

  // Uniform in [0, 1): 24 random mantissa bits, never exactly 1.
  float uniform() { return static_cast<float>(nextU32() >> 8) * 0x1p-24f; }
  Vec2 uniform2() {
    const float a = uniform();
    return {a, uniform()};
  }

 private:
  uint64_t state_ = 0;
  uint64_t inc_ = 1;
};

}  // namespace ll
