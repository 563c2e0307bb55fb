// LIGHTLAB_ANSWER_FILE A1.5: the student tree holds this file as object code only.
#include "scene/texture_filter.h"

#include <cmath>

#include "tasks/framework_answer.h"

namespace ll {

Rgb bilinearLookup(const Image& image, Vec2 uv) {
  LIGHTLAB_ANSWER_GUARD("A1.5", "ll::bilinearLookup (the framework's texture filter)");
  const int w = image.width(), h = image.height();
  const float x = (uv.x - std::floor(uv.x)) * static_cast<float>(w) - 0.5f;
  const float y = (1.0f - (uv.y - std::floor(uv.y))) * static_cast<float>(h) - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float tx = x - fx, ty = y - fy;
  auto texel = [&](int i, int j) { return image.at(((i % w) + w) % w, ((j % h) + h) % h); };
  const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
  return (1 - ty) * ((1 - tx) * texel(ix, iy) + tx * texel(ix + 1, iy)) +
         ty * ((1 - tx) * texel(ix, iy + 1) + tx * texel(ix + 1, iy + 1));
}

}  // namespace ll
