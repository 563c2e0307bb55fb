#include "metrics/pixel_statistics.h"

#include "core/error.h"

namespace ll {

PixelStatistics pixelStatistics(const std::vector<Image>& renders) {
  if (renders.size() < 2) throw UserError("pixel statistics need at least two renders");
  const int w = renders[0].width(), h = renders[0].height();
  for (const Image& r : renders)
    if (r.width() != w || r.height() != h) throw UserError("pixel statistics: the renders differ in size");
  const auto n = static_cast<double>(renders.size());
  PixelStatistics s{Image(w, h), Image(w, h)};
  for (size_t i = 0; i < s.mean.pixelCount(); ++i) {
    glm::dvec3 sum(0.0), sum2(0.0);
    for (const Image& r : renders) {
      const glm::dvec3 v(r.pixels()[i]);
      sum += v;
      sum2 += v * v;
    }
    const glm::dvec3 m = sum / n;
    s.mean.pixels()[i] = Rgb(m);
    s.variance.pixels()[i] = Rgb(glm::max(glm::dvec3(0.0), (sum2 - n * m * m) / (n - 1.0)));
  }
  return s;
}

}  // namespace ll
