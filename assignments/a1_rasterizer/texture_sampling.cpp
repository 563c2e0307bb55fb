// A1.5 Texture sampling: nearest, bilinear, trilinear (mipmapped).
#include "a1_tasks.h"
#include "render/student_task.h"

namespace ll::a1 {

#if LIGHTLAB_SOLUTION  // A1.5
namespace {

// Bilinear on one level; repeating in both directions, v = 0 the bottom row.
Rgb bilinear(const Image& img, Vec2 uv) {
  const int w = img.width(), h = img.height();
  const float x = (uv.x - std::floor(uv.x)) * static_cast<float>(w) - 0.5f;
  const float y = (1.0f - (uv.y - std::floor(uv.y))) * static_cast<float>(h) - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float tx = x - fx, ty = y - fy;
  const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
  const auto texel = [&](int i, int j) { return img.at(((i % w) + w) % w, ((j % h) + h) % h); };
  return (1 - ty) * ((1 - tx) * texel(ix, iy) + tx * texel(ix + 1, iy)) +
         ty * ((1 - tx) * texel(ix, iy + 1) + tx * texel(ix + 1, iy + 1));
}

}  // namespace
#endif

Rgb sampleTexture(const MipChain& mips, Vec2 uv, float lod, TextureFilter filter) {
#if LIGHTLAB_SOLUTION  // A1.5
  const Image& base = mips.level(0);
  switch (filter) {
    case TextureFilter::Nearest: {
      const int w = base.width(), h = base.height();
      const int i = static_cast<int>(std::floor((uv.x - std::floor(uv.x)) * static_cast<float>(w)));
      const int j = static_cast<int>(std::floor((1.0f - (uv.y - std::floor(uv.y))) * static_cast<float>(h)));
      return base.at(std::clamp(i, 0, w - 1), std::clamp(j, 0, h - 1));
    }
    case TextureFilter::Bilinear:
      return bilinear(base, uv);
    case TextureFilter::Trilinear: {
      if (!(lod > 0.0f)) return bilinear(base, uv);
      const float top = static_cast<float>(mips.levels() - 1);
      const float l = std::min(lod, top);
      const int k = static_cast<int>(std::floor(l));
      const float t = l - static_cast<float>(k);
      const Rgb a = bilinear(mips.level(k), uv);
      return t > 0.0f ? (1.0f - t) * a + t * bilinear(mips.level(k + 1), uv) : a;
    }
  }
  return Rgb(0.0f);
#else
  // Your A1.5 here (see its comment in a1_tasks.h), then delete the line below.
  (void)mips;
  (void)uv;
  (void)lod;
  (void)filter;
  LIGHTLAB_TODO("A1.5", "texture sampling (assignments/a1_rasterizer/texture_sampling.cpp)");
  return Rgb(0.0f);
#endif
}

}  // namespace ll::a1
