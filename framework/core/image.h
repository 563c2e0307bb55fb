// A float RGB image in linear radiance, row-major with (0,0) at the top-left,
// and its file formats: PNG/JPG (8-bit sRGB, via stb), Radiance HDR (.hdr)
// and PFM (.pfm, 32-bit float).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace ll {

class Image {
 public:
  Image() = default;
  Image(int width, int height, Rgb fill = Rgb(0.0f));

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return pixels_.empty(); }
  size_t pixelCount() const { return pixels_.size(); }

  Rgb& at(int x, int y) { return pixels_[static_cast<size_t>(y) * width_ + x]; }
  const Rgb& at(int x, int y) const { return pixels_[static_cast<size_t>(y) * width_ + x]; }
  std::vector<Rgb>& pixels() { return pixels_; }
  const std::vector<Rgb>& pixels() const { return pixels_; }

  Rgb mean() const;

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<Rgb> pixels_;
};

// sRGB transfer function on one linear channel in [0,1] and back.
float linearToSrgb(float linear);
float srgbToLinear(float encoded);
// round(255 * linearToSrgb(linear)) without a pow: a binary search over the
// 255 linear thresholds between codes (fast enough for live display). NaN -> 0.
uint8_t linearToSrgb8(float linear);

// Options for writing 8-bit files: linear * 2^exposure, then sRGB-encoded.
struct ToneMap {
  float exposure = 0.0f;  // stops
};

// Saves by extension: .png, .jpg, .hdr, .pfm. Throws UserError naming the path
// and the allowed extensions on an unknown one, or if the file cannot be written.
void saveImage(const Image& image, const std::string& path, ToneMap tone = {});
// Loads .png/.jpg/.bmp/.tga (sRGB-decoded to linear), .hdr and .pfm.
Image loadImage(const std::string& path);

}  // namespace ll
