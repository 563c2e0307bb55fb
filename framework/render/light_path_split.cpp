#include "render/light_path_split.h"

#include "core/math.h"
#include "metrics/image_metrics.h"

namespace ll {

std::vector<LightPathShare> lightPathShares(const FrameBuffer& fb) {
  std::vector<LightPathShare> out;
  if (!fb.keepsLightPaths()) return out;
  const Image picture = fb.resolve(false);
  double total = 0.0;
  for (const Rgb& p : picture.pixels()) total += static_cast<double>(luminance(p));
  const bool halves = fb.passes() >= 2;
  for (int c = 0; c < kLightPathClassCount; ++c) {
    const LightPathClass cls = lightPathClassAt(c);
    const Image all = fb.resolveLightPath(cls);
    const Image even = halves ? fb.resolveLightPath(cls, 0) : all, odd = halves ? fb.resolveLightPath(cls, 1) : all;
    LightPathShare s;
    s.cls = cls;
    double lum = 0.0, rel = 0.0;
    for (size_t i = 0; i < all.pixels().size(); ++i) {
      lum += static_cast<double>(luminance(all.pixels()[i]));
      for (int ch = 0; ch < 3; ++ch) {
        const auto p = static_cast<double>(picture.pixels()[i][ch]);
        rel += static_cast<double>(even.pixels()[i][ch]) * static_cast<double>(odd.pixels()[i][ch]) * relMseWeight(p);
      }
    }
    s.luminanceShare = total > 0.0 ? lum / total : 0.0;
    s.relMseWithout = rel / static_cast<double>(3 * all.pixels().size());
    out.push_back(s);
  }
  return out;
}

}  // namespace ll
