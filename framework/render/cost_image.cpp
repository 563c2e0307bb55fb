#include "render/cost_image.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "metrics/image_metrics.h"

namespace ll {

Image accelCostImage(const Accelerator& accel, const Camera& camera, CostMetric metric,
                     const std::atomic<bool>* cancel) {
  Image out(camera.width, camera.height);
  const CameraFrame frame(camera);
  tbb::parallel_for(
      tbb::blocked_range<int>(0, camera.height), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y) {
          if (cancel && cancel->load(std::memory_order_relaxed)) return;
          for (int x = 0; x < camera.width; ++x) {
            const Ray ray = referenceCameraRay(camera, frame, static_cast<float>(x) + 0.5f,
                                               static_cast<float>(y) + 0.5f);
            QueryCounters counters;
            Hit hit;
            accel.intersect(ray, hit, counters);
            const auto count = metric == CostMetric::NodesVisited ? counters.nodesVisited
                                                                  : counters.primitivesTested;
            out.at(x, y) = Rgb(static_cast<float>(count));
          }
        }
      });
  if (cancel && cancel->load()) return {};
  return out;
}

Image costHeatmap(const Image& counts, float scaleMax, float* usedMax) {
  // The heatmap of |counts - 0| is exactly the cost mapped through the colormap.
  return differenceHeatmap(counts, Image(counts.width(), counts.height()), DiffMode::Absolute,
                           scaleMax, usedMax);
}

}  // namespace ll
