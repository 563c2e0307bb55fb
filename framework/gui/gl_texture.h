// An OpenGL texture holding an Image for display: linear radiance is exposed
// (2^stops), sRGB-encoded to 8 bits per channel and uploaded as RGBA8.
// Requires a current GL context on the calling thread.
#pragma once

#include <cstdint>

#include "core/image.h"

namespace ll::gui {

class GlTexture {
 public:
  GlTexture() = default;
  ~GlTexture();
  GlTexture(const GlTexture&) = delete;
  GlTexture& operator=(const GlTexture&) = delete;

  void upload(const Image& image, float exposureStops);
  bool valid() const { return id_ != 0; }
  int width() const { return width_; }
  int height() const { return height_; }
  // For ImGui::Image / ImDrawList::AddImage.
  void* imguiId() const { return reinterpret_cast<void*>(static_cast<intptr_t>(id_)); }

 private:
  unsigned id_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace ll::gui
