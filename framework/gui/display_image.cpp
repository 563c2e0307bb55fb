#include "gui/display_image.h"

#include <cmath>

namespace ll::gui {

DisplayImage encodeForDisplay(const Image& linear, float exposureStops) {
  DisplayImage d;
  d.width = linear.width();
  d.height = linear.height();
  d.rgba.resize(linear.pixelCount() * 4);
  const float scale = std::exp2(exposureStops);
  for (size_t i = 0; i < linear.pixelCount(); ++i) {
    const Rgb c = linear.pixels()[i] * scale;
    uint8_t* out = &d.rgba[i * 4];
    for (int k = 0; k < 3; ++k) out[k] = std::isfinite(c[k]) ? linearToSrgb8(c[k]) : 0;
    out[3] = 255;
  }
  return d;
}

}  // namespace ll::gui
