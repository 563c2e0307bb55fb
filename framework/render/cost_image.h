// The per-pixel cost of an accelerator: for the camera ray through each pixel
// centre, how many nodes its closest-hit query visited or how many
// primitives it tested. The picture that shows why one structure is faster.
#pragma once

#include <atomic>

#include "accel/accelerator.h"
#include "core/image.h"
#include "scene/camera.h"

namespace ll {

enum class CostMetric { NodesVisited, PrimitivesTested };

// One value per pixel (the count, in all three channels), camera at its own
// width x height. Deterministic; parallel over rows. Returns an empty image
// if `cancel` becomes true.
Image accelCostImage(const Accelerator& accel, const Camera& camera, CostMetric metric,
                     const std::atomic<bool>* cancel = nullptr);

// The count image as a heatmap (inferno): 0 black, `scaleMax` and above pale
// yellow; scaleMax <= 0 chooses the 99th percentile, written to *usedMax.
Image costHeatmap(const Image& counts, float scaleMax, float* usedMax);

}  // namespace ll
