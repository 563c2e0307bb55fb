#include "scene/material.h"

#include "scene/texture_filter.h"

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
    case Kind::Image:
      return bilinearLookup(*image, uv);
  }
  return Rgb(1.0f);
}

Rgb Material::diffuse(Vec2 uv) const {
  if (texture.kind == Texture::Kind::Checker) return texture.eval(uv);
  if (texture.kind == Texture::Kind::Image) return kd * texture.eval(uv);
  return kd;
}

}  // namespace ll
