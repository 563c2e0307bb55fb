// A reference's named tolerances ({"metric": "relmse", "max": 1e-4} or
// {"metric": "ssim", "min": 0.99}, data/references/README.md) checked against
// an image error, and a Monte Carlo entry's Z-test settings: shared by the
// grader and the reference-image test.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "metrics/image_metrics.h"
#include "metrics/pixel_ztest.h"

namespace ll::grading {

struct ToleranceCheck {
  std::string metric;
  double value = 0.0;  // measured
  double bound = 0.0;  // the tolerance
  bool isMax = true;   // value must be <= bound (else >= bound)
  bool passed = false;
};

// One check per entry of `tolerances` (a JSON array), in order.
std::vector<ToleranceCheck> checkTolerances(const ImageError& error, const nlohmann::json& tolerances);

// The Z-test settings of a Monte Carlo reference entry: its "ztest" object's
// "alpha", "abs_floor", "rel_floor" and "max_rejected" (ZTestSettings'
// defaults where absent).
ZTestSettings zTestSettings(const nlohmann::json& entry);

}  // namespace ll::grading
