// Accumulates the passes of a progressive render: a running sum of linear
// radiance per pixel, the number of completed passes, and a mask of pixels
// that went through an unimplemented student stub.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "core/image.h"

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
  std::atomic<int> passes_{0};
};

}  // namespace ll
