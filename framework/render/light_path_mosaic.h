// The picture split into its light-path classes (render/light_path_class.h),
// side by side: the whole picture first, then each class that holds light,
// each at full size on a grid of ceil(sqrt(n)) columns. Shown by the GUI's
// "light paths" view (fitted to the pane), `render --stats` (OUT.light-paths)
// and the slide figures of presets with that view.
#pragma once

#include <string>
#include <vector>

#include "render/frame_buffer.h"
#include "render/light_path_split.h"

namespace ll {

struct MosaicTile {
  std::string name;                // "picture", or the class's short name: "direct", "indirect", "caustics", ...
  double share = -1.0;             // the class's share of the luminance, 0..1 (-1: the picture)
  double relMseWithout = -1.0;     // relMSE of the picture without the class (light_path_split.h; -1: the picture)
  int x = 0, y = 0, w = 0, h = 0;  // pixels of the mosaic image
  std::string shareText() const;   // "44.7 %", or "" for the picture
  std::string relMseText() const;  // "without: relMSE 0.016", or "" for the picture
  std::string label() const;       // "direct 44.7 %"
};

struct LightPathMosaic {
  Image image;
  std::vector<MosaicTile> tiles;
};

// From a frame buffer that kept its classes (keepsLightPaths()); empty tiles otherwise. Classes whose share of
// the luminance is below 1e-4 are left out.
LightPathMosaic lightPathMosaic(const FrameBuffer& fb);

// The mosaic scaled to fit within width x height (aspect kept, black around it; each output pixel the mean of
// the input pixels whose centres fall in it); its tiles moved with it.
LightPathMosaic fitMosaic(const LightPathMosaic& mosaic, int width, int height);

}  // namespace ll
