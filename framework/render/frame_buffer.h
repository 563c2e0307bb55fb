// Accumulates the passes of a progressive render: a running sum of linear
// radiance per pixel, the number of completed passes, and a mask of pixels
// that went through an unimplemented student stub. Optionally the same sums
// split by light-path class (render/light_path_class.h), kept apart for even
// and odd passes: two independent estimates of each class.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "core/image.h"
#include "render/light_path_class.h"

namespace ll {

class FrameBuffer {
 public:
  FrameBuffer() = default;
  FrameBuffer(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  int passes() const { return passes_.load(); }

  // Adds one pass's sample to pixel (x, y). Each pixel is written by one worker per pass.
  void add(int x, int y, const Rgb& value) {
    sum_[index(x, y)] += value;
    ++count_[index(x, y)];
  }
  void markStub(int x, int y) { stub_[index(x, y)] = 1; }
  // Keeps light-path classes from now on (clears them); techniques that split their estimate fill them.
  void enableLightPaths();
  bool keepsLightPaths() const { return !classSum_.empty(); }
  // Adds one pass's sample, split into kLightPathClassCount classes, to pixel (x, y).
  void addLightPaths(int x, int y, int pass, const Rgb* classes) {
    const size_t half = static_cast<size_t>(pass & 1), base = (index(x, y) * 2 + half) * kLightPathClassCount;
    for (size_t c = 0; c < kLightPathClassCount; ++c) classSum_[base + c] += classes[c];
    ++classCount_[index(x, y) * 2 + half];
  }
  // The mean of class c's samples per pixel: half 0 = even passes, 1 = odd ones, -1 = all.
  Image resolveLightPath(LightPathClass c, int half = -1) const;
  void completePass() { ++passes_; }
  void clear();
  // Drops every sample (and stub mark) but keeps the count of completed passes.
  void clearSamples();

  // Mean of each pixel's samples; pixels that used a stub get magenta stripes.
  Image resolve(bool markStubs = true) const;
  bool anyStub() const;

 private:
  size_t index(int x, int y) const { return static_cast<size_t>(y) * width_ + x; }
  int width_ = 0, height_ = 0;
  std::vector<Rgb> sum_;
  std::vector<uint32_t> count_;  // samples per pixel (a cancelled pass leaves some pixels ahead)
  std::vector<uint8_t> stub_;
  std::vector<Rgb> classSum_;          // [pixel][half][class]
  std::vector<uint32_t> classCount_;   // [pixel][half]
  std::atomic<int> passes_{0};
};

}  // namespace ll
