#include "render/frame_buffer.h"

#include <algorithm>

namespace ll {

FrameBuffer::FrameBuffer(int width, int height)
    : width_(width), height_(height), sum_(static_cast<size_t>(width) * height, Rgb(0.0f)),
      count_(static_cast<size_t>(width) * height, 0u),
      stub_(static_cast<size_t>(width) * height, 0) {}

void FrameBuffer::clear() {
  std::fill(sum_.begin(), sum_.end(), Rgb(0.0f));
  std::fill(count_.begin(), count_.end(), 0u);
  std::fill(stub_.begin(), stub_.end(), 0);
  std::fill(classSum_.begin(), classSum_.end(), Rgb(0.0f));
  std::fill(classCount_.begin(), classCount_.end(), 0u);
  passes_ = 0;
}

void FrameBuffer::enableLightPaths() {
  classSum_.assign(sum_.size() * 2 * kLightPathClassCount, Rgb(0.0f));
  classCount_.assign(sum_.size() * 2, 0u);
}

Image FrameBuffer::resolveLightPath(LightPathClass c, int half) const {
  Image image(width_, height_);
  if (!keepsLightPaths()) return image;
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      Rgb sum(0.0f);
      uint32_t count = 0;
      for (int h = 0; h < 2; ++h) {
        if (half >= 0 && h != half) continue;
        const size_t cell = index(x, y) * 2 + static_cast<size_t>(h);
        sum += classSum_[cell * kLightPathClassCount + static_cast<size_t>(c)];
        count += classCount_[cell];
      }
      image.at(x, y) = count > 0 ? sum / static_cast<float>(count) : Rgb(0.0f);
    }
  return image;
}

void FrameBuffer::clearSamples() {
  const int passes = passes_.load();
  clear();
  passes_ = passes;
}

bool FrameBuffer::anyStub() const { return std::any_of(stub_.begin(), stub_.end(), [](uint8_t s) { return s != 0; }); }

Image FrameBuffer::resolve(bool markStubs) const {
  Image image(width_, height_);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const size_t i = index(x, y);
      image.at(x, y) = count_[i] > 0 ? sum_[i] / static_cast<float>(count_[i]) : Rgb(0.0f);
      // Diagonal stripes, 2 of every 8 pixels, so the picture stays readable.
      if (markStubs && stub_[i] && ((x + y) % 8) < 2) image.at(x, y) = Rgb(1.0f, 0.0f, 1.0f);
    }
  return image;
}

}  // namespace ll
