// An OpenGL texture showing a DisplayImage (8-bit sRGB RGBA). Requires a
// current GL context on the calling thread.
#pragma once

#include <cstdint>

#include "gui/display_image.h"

namespace ll::gui {

class GlTexture {
 public:
  GlTexture() = default;
  ~GlTexture();
  GlTexture(const GlTexture&) = delete;
  GlTexture& operator=(const GlTexture&) = delete;

  void upload(const DisplayImage& image);
  bool valid() const { return id_ != 0; }
  int width() const { return width_; }
  int height() const { return height_; }
  float legendMax() const { return legendMax_; }  // of the DisplayImage last uploaded
  uint64_t version() const { return version_; }    // of the DisplayImage last uploaded
  // For ImGui::Image / ImDrawList::AddImage.
  void* imguiId() const { return reinterpret_cast<void*>(static_cast<intptr_t>(id_)); }

 private:
  unsigned id_ = 0;
  int width_ = 0, height_ = 0;
  float legendMax_ = 0.0f;
  uint64_t version_ = 0;
};

}  // namespace ll::gui
