// A4.1 BVH build: choosing where a node splits.
#include <algorithm>
#ifdef __SSE__
#include <xmmintrin.h>
#endif

#include "a4_tasks.h"
#include "render/student_task.h"

namespace ll::a4 {

#if LIGHTLAB_SOLUTION  // A4.1 (helpers)
namespace {

Bounds3 centroidBounds(std::span<const BuildPrim> prims) {
  Bounds3 b;
  for (const BuildPrim& p : prims) b.extend(p.centroid);
  return b;
}

int widestAxis(const Bounds3& b) {
  const Vec3 e = b.extent();
  return e.x > e.y ? (e.x > e.z ? 0 : 2) : (e.y > e.z ? 1 : 2);
}

// Object median: the lower half of the centroids along `axis` goes left.
size_t equalCounts(std::span<BuildPrim> prims, int axis) {
  const size_t k = prims.size() / 2;
  std::nth_element(prims.begin(), prims.begin() + static_cast<std::ptrdiff_t>(k), prims.end(),
                   [axis](const BuildPrim& a, const BuildPrim& b) { return a.centroid[axis] < b.centroid[axis]; });
  return k;
}

// Spatial median: centroids below the midpoint of the centroids' box go left.
size_t spatialMedian(std::span<BuildPrim> prims, const Bounds3& cb, int axis) {
  const float mid = cb.center()[axis];
  const auto it = std::partition(prims.begin(), prims.end(),
                                 [axis, mid](const BuildPrim& p) { return p.centroid[axis] < mid; });
  const auto k = static_cast<size_t>(it - prims.begin());
  return (k == 0 || k == prims.size()) ? equalCounts(prims, axis) : k;  // rounding put everything on one side
}

constexpr int kMaxBins = 64;

// Binned SAH (Wald, "On fast Construction of SAH-based Bounding Volume
// Hierarchies", 2007) over all three axes.
size_t sahSplit(std::span<BuildPrim> prims, const Bounds3& bounds, const Bounds3& cb, const SplitSettings& s) {
  const size_t n = prims.size();
  // Small nodes need fewer bins: n primitives fill at most n of them.
  const int bins = std::clamp(std::min(s.bins, static_cast<int>(std::min<size_t>(n, kMaxBins)) + 2), 2, kMaxBins);
  const float nodeArea = bounds.halfSurfaceArea();
  if (!(nodeArea > 0.0f)) return n <= static_cast<size_t>(s.maxLeaf) ? 0 : equalCounts(prims, widestAxis(cb));

  // One pass over the primitives fills the bins of all three axes. (Plain
  // structs, initialised only as far as used: this runs once per node.)
  // Each bin's box as two 4-float rows (the 4th lane unused): with SSE the
  // per-primitive min/max is one instruction each.
  struct alignas(16) Bin {
    float lo[4], hi[4];
    size_t count;
    Vec3 min() const { return {lo[0], lo[1], lo[2]}; }
    Vec3 max() const { return {hi[0], hi[1], hi[2]}; }
  };
  Bin binsOf[3][kMaxBins];
  Vec3 scale(0.0f);  // 0 on an axis without extent: everything lands in bin 0 and the axis is skipped
  for (int axis = 0; axis < 3; ++axis) {
    const float extent = cb.max[axis] - cb.min[axis];
    if (extent > 0.0f) scale[axis] = static_cast<float>(bins) / extent;
    for (int i = 0; i < bins; ++i) binsOf[axis][i] = {{kInfinity, kInfinity, kInfinity, 0.0f},
                                                      {-kInfinity, -kInfinity, -kInfinity, 0.0f}, 0};
  }
  for (const BuildPrim& p : prims) {
#ifdef __SSE__
    const __m128 lo = _mm_setr_ps(p.bounds.min.x, p.bounds.min.y, p.bounds.min.z, 0.0f);
    const __m128 hi = _mm_setr_ps(p.bounds.max.x, p.bounds.max.y, p.bounds.max.z, 0.0f);
#endif
    for (int axis = 0; axis < 3; ++axis) {
      Bin& bin = binsOf[axis][std::min(bins - 1, static_cast<int>((p.centroid[axis] - cb.min[axis]) * scale[axis]))];
#ifdef __SSE__
      _mm_store_ps(bin.lo, _mm_min_ps(_mm_load_ps(bin.lo), lo));
      _mm_store_ps(bin.hi, _mm_max_ps(_mm_load_ps(bin.hi), hi));
#else
      for (int k = 0; k < 3; ++k) {
        bin.lo[k] = std::min(bin.lo[k], p.bounds.min[k]);
        bin.hi[k] = std::max(bin.hi[k], p.bounds.max[k]);
      }
#endif
      ++bin.count;
    }
  }

  float bestCost = kInfinity;
  int bestAxis = -1, bestBoundary = 0;  // left = bins [0, bestBoundary)
  for (int axis = 0; axis < 3; ++axis) {
    if (!(scale[axis] > 0.0f)) continue;
    const Bin* bin = binsOf[axis];
    // Sweep from the right: area and count of bins [i, bins).
    float rightArea[kMaxBins];
    size_t rightCount[kMaxBins];
    Bounds3 acc;
    size_t count = 0;
    for (int i = bins - 1; i > 0; --i) {
      acc.min = glm::min(acc.min, bin[i].min());  // (an empty bin's lo is +inf, its hi -inf)
      acc.max = glm::max(acc.max, bin[i].max());
      count += bin[i].count;
      rightArea[i] = acc.halfSurfaceArea();
      rightCount[i] = count;
    }
    acc = Bounds3{};
    count = 0;
    for (int i = 1; i < bins; ++i) {
      acc.min = glm::min(acc.min, bin[i - 1].min());
      acc.max = glm::max(acc.max, bin[i - 1].max());
      count += bin[i - 1].count;
      const size_t nRight = rightCount[i];
      if (count == 0 || nRight == 0) continue;
      const float cost = s.traversalCost + s.intersectionCost *
                                               (acc.halfSurfaceArea() * static_cast<float>(count) +
                                                rightArea[i] * static_cast<float>(nRight)) /
                                               nodeArea;
      if (cost < bestCost) {
        bestCost = cost;
        bestAxis = axis;
        bestBoundary = i;
      }
    }
  }
  const float leafCost = s.intersectionCost * static_cast<float>(n);
  if (n <= static_cast<size_t>(s.maxLeaf) && leafCost <= bestCost) return 0;
  if (bestAxis < 0) return equalCounts(prims, widestAxis(cb));

  const float lo = cb.min[bestAxis], axisScale = scale[bestAxis];
  const auto it = std::partition(prims.begin(), prims.end(), [&](const BuildPrim& p) {
    return std::min(bins - 1, static_cast<int>((p.centroid[bestAxis] - lo) * axisScale)) < bestBoundary;
  });
  return static_cast<size_t>(it - prims.begin());
}

}  // namespace
#endif

size_t splitPrimitives(std::span<BuildPrim> prims, const Bounds3& bounds, const SplitSettings& settings) {
#if LIGHTLAB_SOLUTION  // A4.1
  const size_t n = prims.size();
  const bool fitsLeaf = n <= static_cast<size_t>(settings.maxLeaf);
  const Bounds3 cb = centroidBounds(prims);
  const int axis = widestAxis(cb);
  if (!(cb.max[axis] > cb.min[axis]))  // identical centroids: no plane separates them
    return fitsLeaf ? 0 : n / 2;
  switch (settings.method) {
    case SplitMethod::Median:
      return fitsLeaf ? 0 : spatialMedian(prims, cb, axis);
    case SplitMethod::EqualCounts:
      return fitsLeaf ? 0 : equalCounts(prims, axis);
    case SplitMethod::Sah:
      return sahSplit(prims, bounds, cb, settings);
  }
  return 0;
#else
  // Your A4.1 here (see its comment in a4_tasks.h), then delete the line below.
  (void)prims;
  (void)bounds;
  (void)settings;
  LIGHTLAB_TODO_EXACT("A4.1", "BVH build: splitting a node (assignments/a4_acceleration/bvh_split.cpp)");
  return 0;
#endif
}

}  // namespace ll::a4
