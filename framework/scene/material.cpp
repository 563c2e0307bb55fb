#include "scene/material.h"

namespace ll {

Rgb Texture::eval(Vec2 uv) const {
  switch (kind) {
    case Kind::None:
      return Rgb(1.0f);
    case Kind::Checker: {
      const auto iu = static_cast<long>(std::floor(uv.x * squares.x));
      const auto iv = static_cast<long>(std::floor(uv.y * squares.y));
      return ((iu + iv) & 1) == 0 ? colorA : colorB;
    }
    case Kind::Image: {
      // Bilinear, repeating; texel centres at (i + 0.5) / size; v = 0 is the bottom row.
      const int w = image->width(), h = image->height();
      const float x = (uv.x - std::floor(uv.x)) * static_cast<float>(w) - 0.5f;
      const float y = (1.0f - (uv.y - std::floor(uv.y))) * static_cast<float>(h) - 0.5f;
      const float fx = std::floor(x), fy = std::floor(y);
      const float tx = x - fx, ty = y - fy;
      auto texel = [&](int i, int j) {
        return image->at(((i % w) + w) % w, ((j % h) + h) % h);
      };
      const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
      return (1 - ty) * ((1 - tx) * texel(ix, iy) + tx * texel(ix + 1, iy)) +
             ty * ((1 - tx) * texel(ix, iy + 1) + tx * texel(ix + 1, iy + 1));
    }
  }
  return Rgb(1.0f);
}

Rgb Material::diffuse(Vec2 uv) const {
  if (texture.kind == Texture::Kind::Checker) return texture.eval(uv);
  if (texture.kind == Texture::Kind::Image) return kd * texture.eval(uv);
  return kd;
}

}  // namespace ll
