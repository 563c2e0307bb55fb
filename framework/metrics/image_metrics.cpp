#include "metrics/image_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace ll {

namespace {

std::string sizeString(const Image& image) {
  return std::to_string(image.width()) + "x" + std::to_string(image.height());
}

void requireSameSize(const char* what, const Image& a, const Image& b) {
  if (a.width() != b.width() || a.height() != b.height())
    throwUserError(std::string(what) + ": image sizes differ (" + sizeString(a) + " vs " +
                   sizeString(b) + ")");
  if (a.empty()) throwUserError(std::string(what) + ": cannot compare empty images");
}

// --- SSIM ----------------------------------------------------------------------

constexpr int kSsimWindow = 11;  // Gaussian window side
constexpr double kSsimSigma = 1.5;
constexpr double kSsimC1 = 0.01 * 0.01;  // (K1 L)^2 with K1 = 0.01, dynamic range L = 1
constexpr double kSsimC2 = 0.03 * 0.03;  // (K2 L)^2 with K2 = 0.03

// Luma of the sRGB-encoded image (linearToSrgb clamps to [0,1]).
std::vector<double> encodedLuma(const Image& image) {
  std::vector<double> luma(image.pixelCount());
  for (size_t i = 0; i < luma.size(); ++i) {
    const Rgb& p = image.pixels()[i];
    const Rgb encoded(linearToSrgb(p.r), linearToSrgb(p.g), linearToSrgb(p.b));
    luma[i] = static_cast<double>(luminance(encoded));
  }
  return luma;
}

// The SSIM formula for one window's weighted statistics.
double ssimFromMoments(double muX, double muY, double xx, double yy, double xy) {
  const double varX = xx - muX * muX;
  const double varY = yy - muY * muY;
  const double cov = xy - muX * muY;
  return ((2.0 * muX * muY + kSsimC1) * (2.0 * cov + kSsimC2)) /
         ((muX * muX + muY * muY + kSsimC1) * (varX + varY + kSsimC2));
}

std::array<double, kSsimWindow> gaussianWindow() {
  std::array<double, kSsimWindow> w{};
  double sum = 0.0;
  for (int i = 0; i < kSsimWindow; ++i) {
    const double d = i - kSsimWindow / 2;
    w[i] = std::exp(-d * d / (2.0 * kSsimSigma * kSsimSigma));
    sum += w[i];
  }
  for (double& v : w) v /= sum;
  return w;
}

// Separable 'valid' filtering with the Gaussian window: the result has
// (w - 10) x (h - 10) entries, one per window position inside the image.
std::vector<double> filterValid(const std::vector<double>& src, int w, int h,
                                const std::array<double, kSsimWindow>& kernel) {
  const int ow = w - (kSsimWindow - 1), oh = h - (kSsimWindow - 1);
  std::vector<double> rows(static_cast<size_t>(ow) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < ow; ++x) {
      double s = 0.0;
      const double* in = &src[static_cast<size_t>(y) * w + x];
      for (int k = 0; k < kSsimWindow; ++k) s += kernel[k] * in[k];
      rows[static_cast<size_t>(y) * ow + x] = s;
    }
  std::vector<double> out(static_cast<size_t>(ow) * oh);
  for (int y = 0; y < oh; ++y)
    for (int x = 0; x < ow; ++x) {
      double s = 0.0;
      for (int k = 0; k < kSsimWindow; ++k) s += kernel[k] * rows[static_cast<size_t>(y + k) * ow + x];
      out[static_cast<size_t>(y) * ow + x] = s;
    }
  return out;
}

double meanSsim(const Image& a, const Image& b) {
  const std::vector<double> x = encodedLuma(a), y = encodedLuma(b);
  const int w = a.width(), h = a.height();
  const size_t n = x.size();
  if (w < kSsimWindow || h < kSsimWindow) {
    // Too small for the Gaussian window: the whole image is one window.
    double muX = 0.0, muY = 0.0, xx = 0.0, yy = 0.0, xy = 0.0;
    for (size_t i = 0; i < n; ++i) {
      muX += x[i];
      muY += y[i];
      xx += x[i] * x[i];
      yy += y[i] * y[i];
      xy += x[i] * y[i];
    }
    const double inv = 1.0 / static_cast<double>(n);
    return ssimFromMoments(muX * inv, muY * inv, xx * inv, yy * inv, xy * inv);
  }
  std::vector<double> xx(n), yy(n), xy(n);
  for (size_t i = 0; i < n; ++i) {
    xx[i] = x[i] * x[i];
    yy[i] = y[i] * y[i];
    xy[i] = x[i] * y[i];
  }
  const auto kernel = gaussianWindow();
  const std::vector<double> muX = filterValid(x, w, h, kernel), muY = filterValid(y, w, h, kernel),
                            fXX = filterValid(xx, w, h, kernel), fYY = filterValid(yy, w, h, kernel),
                            fXY = filterValid(xy, w, h, kernel);
  double sum = 0.0;
  for (size_t i = 0; i < muX.size(); ++i) sum += ssimFromMoments(muX[i], muY[i], fXX[i], fYY[i], fXY[i]);
  return sum / static_cast<double>(muX.size());
}

// --- Colormap ------------------------------------------------------------------

// matplotlib's "inferno" (sRGB-encoded), every 15th of its 256 entries:
// 18 control points at t = i/17. Piecewise-linear interpolation between them
// stays within 0.021 of the full table.
constexpr float kInfernoSrgb[18][3] = {
    {0.001462f, 0.000466f, 0.013866f}, {0.037668f, 0.025921f, 0.132232f},
    {0.116656f, 0.047574f, 0.272321f}, {0.217949f, 0.036615f, 0.383522f},
    {0.316282f, 0.053490f, 0.425116f}, {0.410113f, 0.087896f, 0.433098f},
    {0.503493f, 0.121575f, 0.423356f}, {0.596940f, 0.154848f, 0.398125f},
    {0.688653f, 0.192239f, 0.357603f}, {0.775059f, 0.239667f, 0.303526f},
    {0.851384f, 0.302260f, 0.239636f}, {0.912966f, 0.381636f, 0.169755f},
    {0.956852f, 0.475356f, 0.094695f}, {0.981895f, 0.579392f, 0.026250f},
    {0.987464f, 0.690366f, 0.079990f}, {0.973088f, 0.805409f, 0.216877f},
    {0.947594f, 0.917399f, 0.410665f}, {0.988362f, 0.998364f, 0.644924f},
};

// 256 entries in linear RGB: interpolated between the control points in
// sRGB (where the map was designed), then decoded.
const std::array<Rgb, 256>& infernoLinearTable() {
  static const std::array<Rgb, 256> table = [] {
    std::array<Rgb, 256> t{};
    constexpr int kSegments = 17;
    for (int i = 0; i < 256; ++i) {
      const float pos = static_cast<float>(i) * (static_cast<float>(kSegments) / 255.0f);
      const int k = std::min(static_cast<int>(pos), kSegments - 1);
      const float f = pos - static_cast<float>(k);
      for (int c = 0; c < 3; ++c) {
        const float encoded = kInfernoSrgb[k][c] + f * (kInfernoSrgb[k + 1][c] - kInfernoSrgb[k][c]);
        t[static_cast<size_t>(i)][c] = srgbToLinear(encoded);
      }
    }
    return t;
  }();
  return table;
}

// Nearest-rank 99th percentile of the finite values (0 if there are none).
float percentile99(const std::vector<float>& values) {
  std::vector<float> finite;
  finite.reserve(values.size());
  for (float v : values)
    if (std::isfinite(v)) finite.push_back(v);
  if (finite.empty()) return 0.0f;
  const size_t rank = (99 * finite.size() + 99) / 100;  // ceil(0.99 n), >= 1
  const auto nth = finite.begin() + static_cast<std::ptrdiff_t>(rank - 1);
  std::nth_element(finite.begin(), nth, finite.end());
  return *nth;
}

}  // namespace

double relativeMse(const Image& a, const Image& b) {
  requireSameSize("relativeMse", a, b);
  double rel = 0.0;
  for (size_t i = 0; i < a.pixelCount(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = static_cast<double>(a.pixels()[i][c]) - static_cast<double>(b.pixels()[i][c]);
      const double vb = static_cast<double>(b.pixels()[i][c]);
      rel += d * d * relMseWeight(vb);
    }
  return rel / (3.0 * static_cast<double>(a.pixelCount()));
}

ImageError compareImages(const Image& a, const Image& b) {
  requireSameSize("compareImages", a, b);
  double sq = 0.0, rel = 0.0, sqClamped = 0.0, maxAbs = 0.0, sumA = 0.0, sumB = 0.0;
  for (size_t i = 0; i < a.pixelCount(); ++i) {
    const Rgb& pa = a.pixels()[i];
    const Rgb& pb = b.pixels()[i];
    for (int c = 0; c < 3; ++c) {
      const double va = static_cast<double>(pa[c]), vb = static_cast<double>(pb[c]);
      const double d = va - vb;
      sq += d * d;
      rel += d * d * relMseWeight(vb);
      const double dc = std::clamp(va, 0.0, 1.0) - std::clamp(vb, 0.0, 1.0);
      sqClamped += dc * dc;
      // Written so that a NaN difference propagates instead of being skipped.
      if (!(std::abs(d) <= maxAbs)) maxAbs = std::abs(d);
      sumA += va;
      sumB += vb;
    }
  }
  const double count = 3.0 * static_cast<double>(a.pixelCount());
  ImageError e;
  e.rmse = std::sqrt(sq / count);
  e.relmse = rel / count;
  const double mseClamped = sqClamped / count;
  e.psnr = mseClamped > 0.0 ? -10.0 * std::log10(mseClamped)
           : mseClamped == 0.0 ? std::numeric_limits<double>::infinity()
                               : mseClamped;  // NaN stays NaN
  e.ssim = meanSsim(a, b);
  e.maxAbs = maxAbs;
  e.meanA = sumA / count;
  e.meanB = sumB / count;
  return e;
}

std::vector<std::string> metricNames() { return {"rmse", "relmse", "psnr", "ssim", "maxabs"}; }

double metricValue(const ImageError& error, std::string_view name) {
  if (name == "rmse") return error.rmse;
  if (name == "relmse") return error.relmse;
  if (name == "psnr") return error.psnr;
  if (name == "ssim") return error.ssim;
  if (name == "maxabs") return error.maxAbs;
  throwUserError("unknown metric '" + std::string(name) + "' (allowed: " + joinNames(metricNames()) +
                 ")");
}

Rgb errorColormap(float t) {
  if (!(t >= 0.0f)) t = std::isnan(t) ? 1.0f : 0.0f;
  t = std::min(t, 1.0f);
  const auto& table = infernoLinearTable();
  const float pos = t * 255.0f;
  const int i = std::min(static_cast<int>(pos), 254);
  const float f = pos - static_cast<float>(i);
  return glm::mix(table[static_cast<size_t>(i)], table[static_cast<size_t>(i) + 1], f);
}

Image differenceHeatmap(const Image& a, const Image& b, DiffMode mode, float scaleMax, float* usedMax) {
  requireSameSize("differenceHeatmap", a, b);
  std::vector<float> errors(a.pixelCount());
  for (size_t i = 0; i < errors.size(); ++i) {
    const Rgb& pa = a.pixels()[i];
    const Rgb& pb = b.pixels()[i];
    const Rgb d = glm::abs(pa - pb);
    float e = (d.r + d.g + d.b) / 3.0f;
    if (mode == DiffMode::Relative) e /= std::max((pb.r + pb.g + pb.b) / 3.0f, 0.0f) + 1e-2f;
    errors[i] = e;
  }

  float scale = scaleMax;
  if (!(scale > 0.0f)) {
    scale = percentile99(errors);
    if (!(scale > 0.0f)) {
      scale = 0.0f;
      for (float e : errors)
        if (std::isfinite(e)) scale = std::max(scale, e);
    }
    if (!(scale > 0.0f)) scale = 1.0f;
  }
  if (usedMax) *usedMax = scale;

  Image out(a.width(), a.height());
  for (size_t i = 0; i < errors.size(); ++i)
    out.pixels()[i] = std::isfinite(errors[i]) ? errorColormap(errors[i] / scale) : errorColormap(1.0f);
  return out;
}

Image withLegend(const Image& heatmap, float maxValue) {
  if (heatmap.empty()) throwUserError("withLegend: empty heatmap");
  if (!std::isfinite(maxValue) || !(maxValue > 0.0f))
    throwUserError("withLegend: scale maximum must be a finite number > 0 (got " +
                   std::to_string(maxValue) + ")");
  const int w = heatmap.width(), h = heatmap.height();
  Image out(w, h + kLegendHeight, Rgb(0.0f));
  std::copy(heatmap.pixels().begin(), heatmap.pixels().end(), out.pixels().begin());

  // Strip layout (rows from the top of the strip): 0-2 gap, 3-16 colour bar,
  // 17-22 tick marks, 23 gap.
  constexpr int kBarTop = 3, kBarBottom = 17, kTickBottom = 23;
  for (int x = 0; x < w; ++x) {
    const float t = w > 1 ? static_cast<float>(x) / static_cast<float>(w - 1) : 0.0f;
    const Rgb colour = errorColormap(t);
    for (int y = kBarTop; y < kBarBottom; ++y) out.at(x, h + y) = colour;
  }
  const int ticks[3] = {0, (w - 1) / 2, w - 1};  // scale 0, 0.5, 1
  for (int x : ticks)
    for (int y = kBarBottom; y < kTickBottom; ++y) out.at(x, h + y) = Rgb(1.0f);
  return out;
}

}  // namespace ll
