// Images as the screen shows them: 8-bit sRGB RGBA bytes, made on the
// background worker and uploaded by the UI thread.
#pragma once

#include <cstdint>
#include <vector>

#include "core/image.h"

namespace ll::gui {

struct DisplayImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // row-major, top row first, alpha 255
  float legendMax =
      0.0f;  // a heatmap: the value its brightest colour stands for; 0 = a plain image
  uint64_t version = 0;  // the pane image's version these bytes show (0: not a pane image)
};

// linear * 2^exposureStops, clamped to [0,1], sRGB-encoded; NaN/Inf -> 0.
DisplayImage encodeForDisplay(const Image& linear, float exposureStops);

}  // namespace ll::gui
