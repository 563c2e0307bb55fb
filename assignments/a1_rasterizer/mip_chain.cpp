#include "mip_chain.h"

#include <algorithm>

namespace ll::a1 {

MipChain::MipChain(const Image& image) {
  levels_.push_back(image);
  while (levels_.back().width() > 1 || levels_.back().height() > 1) {
    const Image& src = levels_.back();
    Image dst(std::max(1, src.width() / 2), std::max(1, src.height() / 2));
    for (int y = 0; y < dst.height(); ++y)
      for (int x = 0; x < dst.width(); ++x) {
        const int x0 = std::min(2 * x, src.width() - 1), x1 = std::min(2 * x + 1, src.width() - 1);
        const int y0 = std::min(2 * y, src.height() - 1), y1 = std::min(2 * y + 1, src.height() - 1);
        dst.at(x, y) = 0.25f * (src.at(x0, y0) + src.at(x1, y0) + src.at(x0, y1) + src.at(x1, y1));
      }
    levels_.push_back(std::move(dst));
  }
}

}  // namespace ll::a1
