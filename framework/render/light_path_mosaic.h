// The picture split into its light-path classes (render/light_path_class.h),
// side by side: the whole picture first, then each class that holds light,
// on a grid the size of the frame (each tile the frame scaled down by the
// grid's columns, so tiles keep the camera's aspect). Shown by the GUI's
// "light paths" view and the slide figures of presets with that view.
#pragma once

#include <string>
#include <vector>

#include "render/frame_buffer.h"
#include "render/light_path_split.h"

namespace ll {

struct MosaicTile {
  std::string label;           // "picture" or "direct-lighting 44.7 %"
  int x = 0, y = 0, w = 0, h = 0;  // pixels of the mosaic image
};

struct LightPathMosaic {
  Image image;
  std::vector<MosaicTile> tiles;
};

// From a frame buffer that kept its classes (keepsLightPaths()); empty tiles otherwise. Classes whose share of
// the luminance is below 1e-4 are left out.
LightPathMosaic lightPathMosaic(const FrameBuffer& fb);

}  // namespace ll
