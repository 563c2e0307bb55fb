#include "render/light_path_mosaic.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ll {

namespace {

// img scaled down by an integer factor (box filter), written at (x0, y0) of dst.
void blitScaled(const Image& img, int factor, Image& dst, int x0, int y0) {
  const int w = img.width() / factor, h = img.height() / factor;
  const float n = static_cast<float>(factor * factor);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      Rgb sum(0.0f);
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx) sum += img.at(x * factor + dx, y * factor + dy);
      dst.at(x0 + x, y0 + y) = sum / n;
    }
}

}  // namespace

LightPathMosaic lightPathMosaic(const FrameBuffer& fb) {
  LightPathMosaic m;
  const Image picture = fb.resolve(false);
  m.image = Image(picture.width(), picture.height(), Rgb(0.0f));
  if (!fb.keepsLightPaths()) {
    m.image = picture;
    return m;
  }
  std::vector<std::pair<std::string, Image>> shown{{"picture", picture}};
  for (const LightPathShare& s : lightPathShares(fb)) {
    if (s.luminanceShare < 1e-4) continue;
    char label[96];
    std::snprintf(label, sizeof label, "%s %.1f %%", lightPathClassName(s.cls), 100.0 * s.luminanceShare);
    shown.emplace_back(label, fb.resolveLightPath(s.cls));
  }
  const int n = static_cast<int>(shown.size());
  const int cols = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const int rows = (n + cols - 1) / cols;
  const int factor = std::max(cols, rows);
  const int tw = picture.width() / factor, th = picture.height() / factor;
  // Centre the grid in the frame.
  const int ox = (picture.width() - cols * tw) / 2, oy = (picture.height() - rows * th) / 2;
  for (int i = 0; i < n; ++i) {
    const int x = ox + (i % cols) * tw, y = oy + (i / cols) * th;
    blitScaled(shown[static_cast<size_t>(i)].second, factor, m.image, x, y);
    m.tiles.push_back({shown[static_cast<size_t>(i)].first, x, y, tw, th});
  }
  return m;
}

}  // namespace ll
