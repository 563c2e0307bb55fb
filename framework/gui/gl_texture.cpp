#include "gui/gl_texture.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <GL/gl.h>

namespace ll::gui {

GlTexture::~GlTexture() {
  if (id_ != 0) glDeleteTextures(1, &id_);
}

void GlTexture::upload(const Image& image, float exposureStops) {
  if (image.empty()) return;
  const float scale = std::exp2(exposureStops);
  std::vector<uint8_t> bytes(image.pixelCount() * 4);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Rgb c = image.at(x, y) * scale;
      uint8_t* out = &bytes[(static_cast<size_t>(y) * image.width() + x) * 4];
      for (int k = 0; k < 3; ++k) {
        const float v = std::isfinite(c[k]) ? std::clamp(c[k], 0.0f, 1.0f) : 0.0f;
        out[k] = static_cast<uint8_t>(std::lround(linearToSrgb(v) * 255.0f));
      }
      out[3] = 255;
    }
  if (id_ == 0) glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);  // show pixels as pixels when zoomed
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width(), image.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE,
               bytes.data());
  width_ = image.width();
  height_ = image.height();
}

}  // namespace ll::gui
