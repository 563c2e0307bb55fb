#include "render/light_path_mosaic.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ll {

namespace {

void blit(const Image& src, Image& dst, int x0, int y0) {
  for (int y = 0; y < src.height(); ++y)
    for (int x = 0; x < src.width(); ++x) dst.at(x0 + x, y0 + y) = src.at(x, y);
}

}  // namespace

std::string MosaicTile::shareText() const {
  if (share < 0.0) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %%", 100.0 * share);
  return text;
}

std::string MosaicTile::relMseText() const {
  if (relMseWithout < 0.0) return "";
  char text[48];
  std::snprintf(text, sizeof text, "without: relMSE %.2g", relMseWithout);
  return text;
}

std::string MosaicTile::label() const { return share < 0.0 ? name : name + " " + shareText(); }

LightPathMosaic lightPathMosaic(const FrameBuffer& fb) {
  LightPathMosaic m;
  const Image picture = fb.resolve(false);
  if (!fb.keepsLightPaths()) {
    m.image = picture;
    return m;
  }
  std::vector<std::pair<MosaicTile, Image>> shown{{MosaicTile{"picture"}, picture}};
  for (const LightPathShare& s : lightPathShares(fb))
    if (s.luminanceShare >= 1e-4)
      shown.push_back({MosaicTile{lightPathClassShortName(s.cls), s.luminanceShare, s.relMseWithout},
                       fb.resolveLightPath(s.cls)});
  const int n = static_cast<int>(shown.size());
  const int cols = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const int rows = (n + cols - 1) / cols;
  const int w = picture.width(), h = picture.height(), gap = std::max(1, w / 64);
  m.image = Image(cols * w + (cols - 1) * gap, rows * h + (rows - 1) * gap, Rgb(0.0f));
  for (int i = 0; i < n; ++i) {
    MosaicTile t = shown[static_cast<size_t>(i)].first;
    t.x = (i % cols) * (w + gap);
    t.y = (i / cols) * (h + gap);
    t.w = w;
    t.h = h;
    blit(shown[static_cast<size_t>(i)].second, m.image, t.x, t.y);
    m.tiles.push_back(t);
  }
  return m;
}

LightPathMosaic fitMosaic(const LightPathMosaic& mosaic, int width, int height) {
  const Image& src = mosaic.image;
  const double scale = std::min(static_cast<double>(width) / src.width(), static_cast<double>(height) / src.height());
  const int w = std::max(1, static_cast<int>(src.width() * scale)), h = std::max(1, static_cast<int>(src.height() * scale));
  const int ox = (width - w) / 2, oy = (height - h) / 2;
  LightPathMosaic out;
  out.image = Image(width, height, Rgb(0.0f));
  std::vector<Rgb> sum(static_cast<size_t>(w) * static_cast<size_t>(h), Rgb(0.0f));
  std::vector<int> count(sum.size(), 0);
  for (int y = 0; y < src.height(); ++y)
    for (int x = 0; x < src.width(); ++x) {
      const int dx = std::min(w - 1, static_cast<int>((x + 0.5) * scale));
      const int dy = std::min(h - 1, static_cast<int>((y + 0.5) * scale));
      const size_t i = static_cast<size_t>(dy) * static_cast<size_t>(w) + static_cast<size_t>(dx);
      sum[i] += src.at(x, y);
      ++count[i];
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
      if (count[i] > 0) out.image.at(ox + x, oy + y) = sum[i] / static_cast<float>(count[i]);
    }
  for (MosaicTile t : mosaic.tiles) {
    t.x = ox + static_cast<int>(t.x * scale);
    t.y = oy + static_cast<int>(t.y * scale);
    t.w = static_cast<int>(t.w * scale);
    t.h = static_cast<int>(t.h * scale);
    out.tiles.push_back(t);
  }
  return out;
}

}  // namespace ll
