// Is a Monte Carlo image a correct estimate of the reference? A per-pixel
// two-sided Z-test of the test image against a reference mean image, with the
// variance of the test's per-pixel estimator (at the same samples per pixel)
// from a reference variance image, and Sidak's correction for the many
// pixels tested at once -- as Mitsuba 3 tests its integrators. A correct
// renderer fails with probability about `alpha` whatever the image size; a
// biased one fails once the bias exceeds a few standard deviations anywhere.
#pragma once

#include "core/image.h"

namespace ll {

struct ZTestSettings {
  double alpha = 0.01;  // significance of the whole image (family-wise)
  // Added to every standard deviation: floating-point differences between
  // correct implementations of a pixel that is not random (lit, or in full
  // shadow), in linear radiance: absFloor + relFloor * |mean|.
  double absFloor = 1e-4;
  double relFloor = 1e-3;
  // Rejected pixel channels tolerated. 0 is the strict family-wise test; a
  // few allow for the heavy tails a Gaussian test does not model (a pixel
  // that a 18x brighter light covers by 0.2 % sees it in 0, 1 or 2 of its
  // 64 samples), while a wrong renderer is rejected in dozens of pixels.
  size_t maxRejected = 0;
};

struct ZTestResult {
  bool passed = true;
  size_t tests = 0;           // pixels x channels
  size_t rejected = 0;        // tests whose p-value is below the corrected level
  double minPValue = 1.0;     // the smallest p-value
  double correctedAlpha = 0;  // Sidak: 1 - (1 - alpha)^(1 / tests)
  int worstX = -1, worstY = -1;  // pixel of the smallest p-value
  double worstZ = 0.0;           // its z score (test - mean) / sigma
  size_t nonFinite = 0;          // NaN/Inf test pixels (each rejected)
};

// Precondition: all three images have the same size (else UserError).
// `variance`: per pixel and channel, the variance of one test render's value.
ZTestResult pixelZTest(const Image& test, const Image& mean, const Image& variance, const ZTestSettings& s = {});

}  // namespace ll
