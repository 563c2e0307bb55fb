// Image error metrics: how far a rendered image `a` is from a reference `b`,
// as single numbers (compareImages) and as a picture of where the error is
// (differenceHeatmap + withLegend). `b` is always the reference.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/image.h"

namespace ll {

// Error of a test image `a` against a reference `b` of the same size. Unless a
// field says otherwise, averages run over every pixel and all three channels
// of the linear (not sRGB-encoded, not clamped) values. Non-finite pixel
// values are not filtered out: they make the affected fields NaN or inf.
// ImageError::relmse alone (no SSIM): cheap enough for a curve of many images. Same sizes required.
double relativeMse(const Image& a, const Image& b);

struct ImageError {
  // Root-mean-square error sqrt(mean (a-b)^2), in the images' own linear units
  // (radiance). 0 for identical images; lower is better.
  double rmse = 0.0;
  // Relative MSE: mean of (a-b)^2 / (b^2 + 1e-2), dimensionless. Dividing by
  // the reference value weights errors in dark regions as much as in bright
  // ones; the 1e-2 keeps black reference pixels from dividing by zero.
  // Lower is better.
  double relmse = 0.0;
  // Peak signal-to-noise ratio 10 log10(1 / MSE) in decibels, with both images
  // clamped to [0,1] first (peak value 1). +infinity when the clamped images
  // are equal; higher is better (30 dB and above is hard to tell apart).
  double psnr = 0.0;
  // Mean structural similarity (Wang, Bovik, Sheikh, Simoncelli 2004,
  // "Image Quality Assessment: From Error Visibility to Structural
  // Similarity"), dimensionless in [-1,1], 1 = identical, higher is better.
  // Computed on the luma 0.2126 R' + 0.7152 G' + 0.0722 B' of the
  // sRGB-encoded images clamped to [0,1], with an 11x11 Gaussian window
  // (sigma 1.5, weights summing to 1), C1 = 0.01^2, C2 = 0.03^2, averaged
  // over every window position that lies fully inside the image. An image
  // narrower or lower than 11 pixels is treated as one window with equal
  // weights.
  double ssim = 0.0;
  // Largest |a-b| over all pixels and channels, linear units.
  double maxAbs = 0.0;
  // Mean value of a and of b (over pixels and channels), linear units: a quick
  // check for an overall brightness mismatch.
  double meanA = 0.0;
  double meanB = 0.0;
};

// Compares test image `a` with reference `b`. Throws UserError if the sizes
// differ ("... (WxH vs WxH)") or the images are empty.
// relMSE's weight of one channel's squared error against reference value b: 1 / (b^2 + 1e-2).
inline double relMseWeight(double b) { return 1.0 / (b * b + 1e-2); }

ImageError compareImages(const Image& a, const Image& b);

// The metric names metricValue accepts, in a fixed order:
// rmse, relmse, psnr, ssim, maxabs.
std::vector<std::string> metricNames();
// One field of `error` by name (see metricNames; exact lower-case match).
// Throws UserError "unknown metric 'x' (allowed: rmse, relmse, psnr, ssim, maxabs)".
double metricValue(const ImageError& error, std::string_view name);

// --- Visualising the error ---------------------------------------------------

// The per-pixel error value a heatmap shows.
enum class DiffMode {
  Absolute,  // mean over the channels of |a-b|, linear units
  Relative,  // that divided by (max(mean over the channels of b, 0) + 1e-2)
};

// The matplotlib "inferno" colormap (van der Walt & Smith), t in [0,1] from
// near-black (0) through purple and orange to pale yellow (1), returned in
// linear RGB so that it shows the published colours once sRGB-encoded on
// save. t is clamped to [0,1]; NaN gives the colour for 1.
Rgb errorColormap(float t);

// One colour per pixel for the error of `a` against reference `b` (sizes must
// match, else UserError): error value 0 maps to errorColormap(0), scaleMax
// and above to errorColormap(1). If scaleMax <= 0 the scale is chosen
// automatically as the 99th percentile of the finite error values
// (nearest-rank: the smallest error value that at least 99% of the pixels do
// not exceed), so that a few fireflies don't wash out the picture; if that is
// 0 the largest finite error is used, and if that is 0 too (identical
// images), 1. The scale actually used is stored in *usedMax unless usedMax is
// null. Pixels with a non-finite error get the brightest colour.
Image differenceHeatmap(const Image& a, const Image& b, DiffMode mode, float scaleMax = 0.0f,
                        float* usedMax = nullptr);

// Height in pixels of the strip withLegend appends.
constexpr int kLegendHeight = 24;

// `heatmap` with a kLegendHeight-pixel strip appended below: a bar with the
// colormap from 0 (left edge) to 1 (right edge) on a black background and
// small white tick marks under it at 0, 0.5 and 1 of the scale. `maxValue` is
// the error value the right end stands for (the usedMax of
// differenceHeatmap); the bar itself does not depend on it (no text labels
// are drawn), so print it next to the image. Throws UserError for an empty
// heatmap or a maxValue that is not finite and > 0.
Image withLegend(const Image& heatmap, float maxValue);

}  // namespace ll
