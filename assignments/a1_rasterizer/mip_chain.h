// A texture's mipmap pyramid: level 0 is the image, each next level halves
// width and height (at least 1 texel) by a 2x2 box filter, down to 1 x 1.
#pragma once

#include <vector>

#include "core/image.h"

namespace ll::a1 {

class MipChain {
 public:
  MipChain() = default;
  explicit MipChain(const Image& image);

  int levels() const { return static_cast<int>(levels_.size()); }
  const Image& level(int k) const { return levels_[static_cast<size_t>(k)]; }

 private:
  std::vector<Image> levels_;
};

}  // namespace ll::a1
