#include "metrics/pixel_ztest.h"

#include <cmath>

#include "core/error.h"

namespace ll {

ZTestResult pixelZTest(const Image& test, const Image& mean, const Image& variance, const ZTestSettings& s) {
  if (test.width() != mean.width() || test.height() != mean.height() || test.width() != variance.width() ||
      test.height() != variance.height() || test.empty())
    throwUserError("statistical test: the test, mean and variance images must have one size (" +
                   std::to_string(test.width()) + "x" + std::to_string(test.height()) + ", " +
                   std::to_string(mean.width()) + "x" + std::to_string(mean.height()) + ", " +
                   std::to_string(variance.width()) + "x" + std::to_string(variance.height()) + ")");
  ZTestResult r;
  r.tests = test.pixelCount() * 3;
  r.correctedAlpha = 1.0 - std::pow(1.0 - s.alpha, 1.0 / static_cast<double>(r.tests));
  for (int y = 0; y < test.height(); ++y)
    for (int x = 0; x < test.width(); ++x)
      for (int c = 0; c < 3; ++c) {
        const double t = static_cast<double>(test.at(x, y)[c]), m = static_cast<double>(mean.at(x, y)[c]);
        const double v = std::max(0.0, static_cast<double>(variance.at(x, y)[c]));
        double p = 0.0, z = 0.0;
        if (!std::isfinite(t)) {
          ++r.nonFinite;
        } else {
          const double sigma = std::sqrt(v) + s.absFloor + s.relFloor * std::abs(m);
          z = (t - m) / sigma;
          p = std::erfc(std::abs(z) / std::sqrt(2.0));  // two-sided
        }
        if (p < r.correctedAlpha) ++r.rejected;
        if (p < r.minPValue) {
          r.minPValue = p;
          r.worstX = x;
          r.worstY = y;
          r.worstZ = z;
        }
      }
  r.passed = r.rejected <= s.maxRejected && r.nonFinite == 0;
  return r;
}

}  // namespace ll
