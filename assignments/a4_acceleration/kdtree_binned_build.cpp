// The binned KD-tree build (framework code; `-a kdtree --set build=binned`),
// the first one LightLab had: top-down, one axis-aligned plane per node,
// chosen by the surface area heuristic among the bin boundaries of each axis
// of the node's cell plus the faces of the primitives' box. O(n) per node
// (one pass counts where every box starts and ends, then O(bins) prices the
// candidates), so O(n log n) for the tree; every node partitions and clips
// from scratch, with no sorted lists to keep. Shevtsov, Soupikov and
// Kapustin, "Highly parallel fast KD-tree construction for interactive ray
// tracing of dynamic scenes", Eurographics 2007, count bins the same way.
//
// Fast where it pays: big nodes count their bins in parallel, and the
// recursion the sweep build shares (kdtree_top_down.h) builds big nodes' two
// subtrees in parallel and reuses its buffers. The trees are the same on any
// number of threads, and the same as the first, serial version made.
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include <emmintrin.h>  // SSE2 (x86-64 baseline): the three axes' bins at once

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "kdtree.h"
#include "kdtree_build_support.h"
#include "kdtree_top_down.h"

namespace ll::a4::kdbuild {

namespace {

// countBins loads a box's max corner as four floats: the fourth is `prim`, still inside the KdPrim.
static_assert(offsetof(KdPrim, box) + sizeof(Bounds3) + sizeof(float) <= sizeof(KdPrim));

// Where a node's boxes start and end, per axis: bin counts and the faces of their box.
struct BinCounts {
  std::array<std::array<uint32_t, kMaxBins>, 3> starts, ends;  // [axis][bin]; bins beyond `bins` unset
  Vec3 first{kInfinity}, last{-kInfinity};                     // per axis: lowest min and highest max face

  explicit BinCounts(int bins) {  // zeroes only the bins in use: most nodes are small
    for (size_t a = 0; a < 3; ++a) {
      std::fill_n(starts[a].begin(), bins, 0u);
      std::fill_n(ends[a].begin(), bins, 0u);
    }
  }

  void add(const BinCounts& o, int bins) {
    for (size_t a = 0; a < 3; ++a)
      for (size_t b = 0; b < static_cast<size_t>(bins); ++b) {
        starts[a][b] += o.starts[a][b];
        ends[a][b] += o.ends[a][b];
      }
    first = glm::min(first, o.first);
    last = glm::max(last, o.last);
  }
};

class Builder : public TopDownBuilder<Builder, std::vector<KdPrim>> {
 public:
  explicit Builder(BuildShared& shared) : TopDownBuilder(shared) {}

 private:
  friend class TopDownBuilder<Builder, std::vector<KdPrim>>;  // calls prims(), bestPlane() and split()

  static const std::vector<KdPrim>& prims(const std::vector<KdPrim>& in) { return in; }

  // Splits `prims` at the plane: below if the box starts below it, above if
  // it ends above it; a box lying in the plane (planar primitive) goes above.
  // So every primitive goes somewhere, and a hit point on the plane is in a
  // cell holding its primitive. A straddling triangle is clipped to each cell.
  void split(const std::vector<KdPrim>& prims, const KdPlane& plane, const Bounds3& cellBelow,
             const Bounds3& cellAbove, std::vector<KdPrim>& below, std::vector<KdPrim>& above) const {
    const int a = plane.axis;
    const float position = plane.position;
    below.clear();
    above.clear();
    for (const KdPrim& p : prims) {
      const bool toBelow = p.box.min[a] < position;
      const bool toAbove = p.box.max[a] > position || (p.box.min[a] == position && p.box.max[a] == position);
      if (toBelow && toAbove && p.prim < sh_.triangleCount) {
        clipInto(p, cellBelow, below);
        clipInto(p, cellAbove, above);
        continue;
      }
      if (toBelow) {
        KdPrim q = p;
        q.box.max[a] = std::min(q.box.max[a], position);
        below.push_back(q);
      }
      if (toAbove) {
        KdPrim q = p;
        q.box.min[a] = std::max(q.box.min[a], position);
        above.push_back(q);
      }
    }
  }

  // Adds triangle p to `out` with its box shrunk to the part inside `cell`
  // (padded by pad, within p's box and the cell); not at all if the
  // triangle stays more than pad away from the cell.
  void clipInto(const KdPrim& p, const Bounds3& cell, std::vector<KdPrim>& out) const {
    const LeafTriangle& t = sh_.triangles[p.prim];
    const Bounds3 b = clippedBox(p, t.p0, t.p1, t.p2, cell, sh_.pad);
    if (!b.empty()) out.push_back({b, p.prim});
  }

  // Counts, in one pass, where the boxes of prims[0, count) start and end:
  // bin b of axis a spans [lo + b / scale, lo + (b + 1) / scale) (the last
  // bin reaches on). The three axes' bins at once, in SSE lanes: (x - lo) *
  // scale, clamped as a float before the conversion -- a NaN (0 * inf, in a
  // cell thinner than float resolution) to bin 0 and anything beyond int's
  // range (far boxes) to the last bin, where the conversion is undefined.
  void countBins(const KdPrim* prims, size_t count, const Vec3& lo, const Vec3& scale, BinCounts& c) const {
    const __m128 lo4 = _mm_setr_ps(lo.x, lo.y, lo.z, 0.0f), scale4 = _mm_setr_ps(scale.x, scale.y, scale.z, 0.0f);
    const __m128 zero = _mm_setzero_ps(), lastBin = _mm_set1_ps(static_cast<float>(sh_.bins - 1));
    // max_ps returns its second operand when either is NaN: a NaN goes to bin 0.
    const auto binsOf = [&](__m128 x) {
      return _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(_mm_mul_ps(_mm_sub_ps(x, lo4), scale4), zero), lastBin));
    };
    __m128 first = _mm_set1_ps(kInfinity), last = _mm_set1_ps(-kInfinity);
    alignas(16) int32_t s[4], e[4];
    for (size_t i = 0; i < count; ++i) {
      // Lanes 0-2 are the box's min (max); lane 3 is the next field's bits, never used. Both loads stay
      // inside the KdPrim (box.max is followed by prim).
      const __m128 boxMin = _mm_loadu_ps(&prims[i].box.min.x), boxMax = _mm_loadu_ps(&prims[i].box.max.x);
      _mm_store_si128(reinterpret_cast<__m128i*>(s), binsOf(boxMin));
      _mm_store_si128(reinterpret_cast<__m128i*>(e), binsOf(boxMax));
      for (size_t a = 0; a < 3; ++a) {
        ++c.starts[a][static_cast<size_t>(s[a])];
        ++c.ends[a][static_cast<size_t>(e[a])];
      }
      first = _mm_min_ps(first, boxMin);
      last = _mm_max_ps(last, boxMax);
    }
    alignas(16) float f[4], l[4];
    _mm_store_ps(f, first);
    _mm_store_ps(l, last);
    c.first = glm::min(c.first, Vec3(f[0], f[1], f[2]));
    c.last = glm::max(c.last, Vec3(l[0], l[1], l[2]));
  }

  // The cheapest bin boundary over all three axes: counts of boxes starting
  // and ending in each bin give the primitives on each side in O(bins).
  // emptyOnly: only planes with no primitive on one side, and their cost
  // without the empty bonus (the true SAH cost, to compare with a leaf's).
  // On a tie the first candidate wins: lower axis, then lower boundary, then the faces.
  KdPlane bestPlane(const std::vector<KdPrim>& prims, const Bounds3& cell, bool emptyOnly) const {
    const int bins = sh_.bins;
    Vec3 scale;
    for (int a = 0; a < 3; ++a) scale[a] = static_cast<float>(bins) / (cell.max[a] - cell.min[a]);
    BinCounts c(bins);
    if (prims.size() >= kParallelPrimitives) {
      c = tbb::parallel_reduce(
          tbb::blocked_range<size_t>(0, prims.size(), 4096), BinCounts(bins),
          [&](const tbb::blocked_range<size_t>& r, BinCounts part) {
            countBins(prims.data() + r.begin(), r.size(), cell.min, scale, part);
            return part;
          },
          [&](BinCounts x, const BinCounts& y) {
            x.add(y, bins);
            return x;
          });
    } else {
      countBins(prims.data(), prims.size(), cell.min, scale, c);
    }

    KdPlane best;
    const float emptySideFactor = emptyOnly ? 1.0f : 1.0f - s_.emptyBonus;  // cost factor of a one-sided plane
    const float n = static_cast<float>(prims.size());
    const float invArea = 1.0f / halfArea(cell);
    const Vec3 extent = glm::max(cell.max - cell.min, Vec3(0.0f));
    for (int a = 0; a < 3; ++a) {
      const float lo = cell.min[a], hi = cell.max[a];
      if (!(hi > lo)) continue;
      // All bin boundaries priced at once (vectorised), then the first cheapest taken.
      std::array<float, kMaxBins> price;
      if (a == 0) priceBoundaries<0>(c, cell, extent, n, invArea, emptyOnly, emptySideFactor, price);
      if (a == 1) priceBoundaries<1>(c, cell, extent, n, invArea, emptyOnly, emptySideFactor, price);
      if (a == 2) priceBoundaries<2>(c, cell, extent, n, invArea, emptyOnly, emptySideFactor, price);
      // The cheapest, four lanes at a time (vectorised): m[l] is the least of price[l], price[l + 4], ...
      const size_t padded = (static_cast<size_t>(bins) + 3) & ~size_t{3};
      std::array<float, 4> m{kInfinity, kInfinity, kInfinity, kInfinity};
      for (size_t b = 0; b < padded; b += 4)
        for (size_t l = 0; l < 4; ++l) m[l] = price[b + l] < m[l] ? price[b + l] : m[l];
      const float least = std::min(std::min(m[0], m[1]), std::min(m[2], m[3]));  // NaN prices never win
      if (least < best.cost) {
        size_t b = 1;
        while (!(price[b] == least)) ++b;  // the first one, as a scan with `<` would take
        best = {a, lo + (hi - lo) * sh_.binFractions[b], least, false};
      }
      // Two more candidates: the faces of the primitives' box, which cut off
      // the cell's empty space in one step (bin boundaries would nibble at it).
      const float first = std::min(hi, c.first[a]), last = std::max(lo, c.last[a]);
      for (const float position : {first, last}) {
        if (!(position > lo && position < hi)) continue;
        Bounds3 cb = cell, ca = cell;
        cb.max[a] = position;
        ca.min[a] = position;
        const float side = position == first ? halfArea(ca) : halfArea(cb);  // the side holding all n
        const float cost = s_.traversalCost + emptySideFactor * s_.intersectionCost * invArea * side * n;
        if (cost < best.cost) best = {a, position, cost, false};
      }
    }
    return best;
  }

  // The SAH cost of every bin boundary b = 1 .. bins - 1 on axis A into
  // cost[b] (infinity where it is no candidate: outside the open cell, or
  // two-sided when emptyOnly), in the same floating-point operations as
  // halfArea() of the two cells, so the choice does not depend on how it is
  // computed. extent: the cell's, clamped at 0 as halfArea() does.
  template <int A>
  void priceBoundaries(const BinCounts& c, const Bounds3& cell, const Vec3& extent, float n, float invArea,
                       bool emptyOnly, float emptySideFactor, std::array<float, kMaxBins>& cost) const {
    const int bins = sh_.bins;
    // Boxes starting below boundary b, and ending below it (prefix sums; converted to floats below, in
    // vector registers).
    std::array<int32_t, kMaxBins> started, ended;
    int32_t nBelow = 0, nEnded = 0;
    for (size_t b = 1; b < static_cast<size_t>(bins); ++b) {
      nBelow += static_cast<int32_t>(c.starts[A][b - 1]);
      nEnded += static_cast<int32_t>(c.ends[A][b - 1]);
      started[b] = nBelow;
      ended[b] = nEnded;
    }
    // halfArea's sum e.x e.y + e.y e.z + e.z e.x, in its order, with e[A] = `length` (> 0 where priced).
    const float ex = extent.x, ey = extent.y, ez = extent.z;
    const auto area = [=](float length) {
      if constexpr (A == 0) return length * ey + ey * ez + ez * length;
      if constexpr (A == 1) return ex * length + length * ez + ez * ex;
      if constexpr (A == 2) return ex * ey + ey * length + length * ex;
    };
    const float lo = cell.min[A], hi = cell.max[A];
    const float* fraction = sh_.binFractions.data();
    const float twoSided = s_.intersectionCost * invArea, oneSided = emptySideFactor * s_.intersectionCost * invArea;
    const float traversal = s_.traversalCost;
    cost[0] = kInfinity;  // no candidate at the cell's face; the rest of the last four lanes neither
    std::fill(cost.begin() + bins, cost.begin() + ((bins + 3) & ~3), kInfinity);
    for (size_t b = 1; b < static_cast<size_t>(bins); ++b) {
      const float position = lo + (hi - lo) * fraction[b];
      const float nB = static_cast<float>(started[b]), nA = n - static_cast<float>(ended[b]);
      // Bitwise & and |: no branches, so the loop vectorises.
      const bool isOneSided = (nB == 0.0f) | (nA == 0.0f);
      const float price =
          traversal + (isOneSided ? oneSided : twoSided) * (area(position - lo) * nB + area(hi - position) * nA);
      const bool candidate = (position > lo) & (position < hi) & (isOneSided | !emptyOnly);
      cost[b] = candidate ? price : kInfinity;
    }
  }
};

}  // namespace

BuildTotals buildBinned(KdTree& tree, std::vector<KdPrim> prims, const KdSettings& s, int maxDepth, float pad) {
  BuildShared shared(tree, s, maxDepth, pad);
  Builder builder(shared);
  std::vector<KdPrim>& root = builder.input(0);
  root = std::move(prims);
  builder.build(root, tree.bounds, 0, 0, 0);
  return builder.takeTree()->writeTree(tree);
}

}  // namespace ll::a4::kdbuild
