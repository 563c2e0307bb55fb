// Per-pixel sample statistics over several renders of the same picture (with
// different seeds): the estimate of the mean and of one render's variance,
// for Monte Carlo references and statistical tests.
#pragma once

#include <vector>

#include "core/image.h"

namespace ll {

struct PixelStatistics {
  Image mean;      // per pixel and channel, the average of the renders
  Image variance;  // the unbiased sample variance of one render's value (n - 1 in the denominator)
};

// Precondition: at least two renders, all of the same size (else UserError).
PixelStatistics pixelStatistics(const std::vector<Image>& renders);

}  // namespace ll
