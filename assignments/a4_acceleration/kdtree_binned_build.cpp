// The binned KD-tree build (framework code), the first one LightLab had and
// kept as the sweep build's yardstick (`-a kdtree --set build=binned`):
// top-down, one axis-aligned plane per node chosen by the surface area
// heuristic among the bin boundaries of each axis of the node's cell, plus
// the faces of the primitives' box. O(n) per node, so O(n log n) for the
// tree, but every node bins, partitions and clips from scratch.
#include <algorithm>
#include <array>
#include <string>

#include "core/phase_progress.h"
#include "kdtree.h"
#include "kdtree_build_support.h"

namespace ll::a4::kdbuild {

namespace {

struct Plane {
  int axis = -1;  // -1: no plane found
  float position = 0.0f;
  float cost = kInfinity;
};

constexpr int kMaxBins = 64;

class Builder {
 public:
  // pad: world-space margin (>= rounding of the clipping) around clipped triangle boxes.
  Builder(KdTree& tree, const KdSettings& s, int maxDepth, float pad)
      : tree_(tree), s_(s), maxDepth_(maxDepth), pad_(pad) {}

  // Appends the subtree of the cell `cell` holding `prims` (consumed) at the
  // end of tree_.nodes. depth: edges from the root; splits: of those, the
  // ones that left primitives on both sides (cutting off empty space does
  // not count against maxDepth, or a small object in a big scene would run
  // out of depth before its primitives are separated).
  void build(std::vector<KdPrim>& prims, const Bounds3& cell, int depth, int splits, int badRefines) {
    const auto index = static_cast<uint32_t>(tree_.nodes.size());
    tree_.nodes.emplace_back();
    // Seconds on a big mesh (3.5 s for 235k triangles): say so every 1024 nodes and at every big node,
    // which is also where a GUI pane's newer request cancels the build (its phase report throws).
    if ((index & 0x3FF) == 0 || prims.size() > 20000)
      reportPhase("kd-tree build (" + std::to_string(index) + " nodes)");
    depth_ = std::max(depth_, depth);
    const size_t n = prims.size();
    const double area = halfArea(cell);
    if (n == 0 || splits >= maxDepth_ || depth >= kKdMaxDepth || tree_.nodes.size() + 2 > kKdMaxNodes)
      return makeLeaf(index, prims, area);
    // A node with few primitives is a leaf unless a plane with nothing on one
    // side lowers its SAH cost: so a wall lying in the cell's face gets a
    // thin slab of its own, and rays crossing the rest of the cell skip it.
    const bool few = n <= static_cast<size_t>(s_.maxLeaf);
    const Plane plane = bestPlane(prims, cell, few);
    const float leafCost = s_.intersectionCost * static_cast<float>(n);
    if (plane.axis < 0 || (few && plane.cost >= leafCost)) return makeLeaf(index, prims, area);
    if (plane.cost >= leafCost) ++badRefines;  // PBRT: a few uphill splits out of local minima; none below 16 primitives
    if ((plane.cost >= leafCost && n < 16) || badRefines >= 3) return makeLeaf(index, prims, area);

    // Partition: below if the box starts below the plane, above if it ends
    // above it; a box lying in the plane (planar primitive) goes above. So
    // every primitive goes somewhere, and a hit point on the plane is in a
    // cell holding its primitive.
    const int a = plane.axis;
    const float split = plane.position;
    Bounds3 cellBelow = cell, cellAbove = cell;
    cellBelow.max[a] = split;
    cellAbove.min[a] = split;
    std::vector<KdPrim> below, above;
    below.reserve(n);
    above.reserve(n);
    for (const KdPrim& p : prims) {
      const bool toBelow = p.box.min[a] < split;
      const bool toAbove = p.box.max[a] > split || (p.box.min[a] == split && p.box.max[a] == split);
      if (toBelow && toAbove && p.prim < tree_.triangleCount) {  // a straddling triangle: clip it
        clipInto(p, cellBelow, below);
        clipInto(p, cellAbove, above);
        continue;
      }
      if (toBelow) {
        KdPrim q = p;
        q.box.max[a] = std::min(q.box.max[a], split);
        below.push_back(q);
      }
      if (toAbove) {
        KdPrim q = p;
        q.box.min[a] = std::max(q.box.min[a], split);
        above.push_back(q);
      }
    }
    std::vector<KdPrim>().swap(prims);  // free before recursing
    sah_ += static_cast<double>(s_.traversalCost) * area;
    const bool belowEmpty = below.empty(), aboveEmpty = above.empty();
    const int nextSplits = splits + (belowEmpty || aboveEmpty ? 0 : 1);
    build(below, cellBelow, depth + 1, nextSplits, badRefines);
    const auto aboveIndex = static_cast<uint32_t>(tree_.nodes.size());
    tree_.nodes[index] = KdNode::interior(a, split, aboveIndex, belowEmpty, aboveEmpty);
    build(above, cellAbove, depth + 1, nextSplits, badRefines);
  }

  int depth() const { return depth_; }
  double sahSum() const { return sah_; }  // sum of cost * half area (divide by the root's)

 private:
  // Adds triangle p to `out` with its box shrunk to the part inside `cell`
  // (padded by pad_, within p's box and the cell); not at all if the
  // triangle stays more than pad_ away from the cell.
  void clipInto(const KdPrim& p, const Bounds3& cell, std::vector<KdPrim>& out) const {
    const LeafTriangle& t = tree_.triangles[p.prim];
    const Bounds3 b = clippedBox(p, t.p0, t.p1, t.p2, cell, pad_);
    if (!b.empty()) out.push_back({b, p.prim});
  }

  void makeLeaf(uint32_t index, const std::vector<KdPrim>& prims, double area) {
    tree_.nodes[index] =
        KdNode::leafNode(static_cast<uint32_t>(tree_.primIds.size()), static_cast<uint32_t>(prims.size()));
    for (const KdPrim& p : prims) tree_.primIds.push_back(p.prim);
    sah_ += static_cast<double>(s_.intersectionCost) * static_cast<double>(prims.size()) * area;
  }

  // The cheapest bin boundary over all three axes: counts of boxes starting
  // and ending in each bin give the primitives on each side in O(bins).
  // emptyOnly: only planes with no primitive on one side, and their cost
  // without the empty bonus (the true SAH cost, to compare with a leaf's).
  Plane bestPlane(const std::vector<KdPrim>& prims, const Bounds3& cell, bool emptyOnly) const {
    Plane best;
    const float emptySideFactor = emptyOnly ? 1.0f : 1.0f - s_.emptyBonus;  // cost factor of a one-sided plane
    const int bins = std::clamp(s_.bins, 2, kMaxBins);
    const float n = static_cast<float>(prims.size());
    const float invArea = 1.0f / halfArea(cell);
    for (int a = 0; a < 3; ++a) {
      const float lo = cell.min[a], hi = cell.max[a];
      if (!(hi > lo)) continue;
      const float scale = static_cast<float>(bins) / (hi - lo);
      std::array<uint32_t, kMaxBins> starts{}, ends{};
      // Clamped as a float before the conversion: (x - lo) * scale is 0 * inf = NaN in a cell thinner than
      // float resolution, and beyond int's range for far boxes (both undefined as an int).
      auto binOf = [&](float x) {
        const float f = (x - lo) * scale;
        return f >= static_cast<float>(bins - 1) ? static_cast<size_t>(bins - 1) : f > 0.0f ? static_cast<size_t>(f) : 0;
      };
      for (const KdPrim& p : prims) {
        ++starts[binOf(p.box.min[a])];
        ++ends[binOf(p.box.max[a])];
      }
      uint32_t nBelow = 0, nEnded = 0;
      for (int b = 1; b < bins; ++b) {
        nBelow += starts[static_cast<size_t>(b - 1)];  // boxes starting below boundary b
        nEnded += ends[static_cast<size_t>(b - 1)];    // boxes ending below boundary b
        const float position = lo + (hi - lo) * (static_cast<float>(b) / static_cast<float>(bins));
        if (!(position > lo && position < hi)) continue;
        Bounds3 cb = cell, ca = cell;
        cb.max[a] = position;
        ca.min[a] = position;
        const float nB = static_cast<float>(nBelow), nA = n - static_cast<float>(nEnded);
        const bool oneSided = nBelow == 0 || nA == 0.0f;
        if (emptyOnly && !oneSided) continue;
        const float cost =
            s_.traversalCost + (oneSided ? emptySideFactor : 1.0f) * s_.intersectionCost * invArea * (halfArea(cb) * nB + halfArea(ca) * nA);
        if (cost < best.cost) best = {a, position, cost};
      }
      // Two more candidates: the faces of the primitives' box, which cut off
      // the cell's empty space in one step (bin boundaries would nibble at it).
      float first = hi, last = lo;
      for (const KdPrim& p : prims) {
        first = std::min(first, p.box.min[a]);
        last = std::max(last, p.box.max[a]);
      }
      for (const float position : {first, last}) {
        if (!(position > lo && position < hi)) continue;
        Bounds3 cb = cell, ca = cell;
        cb.max[a] = position;
        ca.min[a] = position;
        const float side = position == first ? halfArea(ca) : halfArea(cb);  // the side holding all n
        const float cost = s_.traversalCost + emptySideFactor * s_.intersectionCost * invArea * side * n;
        if (cost < best.cost) best = {a, position, cost};
      }
    }
    return best;
  }

  KdTree& tree_;
  const KdSettings& s_;
  int maxDepth_;
  float pad_;
  int depth_ = 0;
  double sah_ = 0.0;
};

}  // namespace

BuildTotals buildBinned(KdTree& tree, std::vector<KdPrim> prims, const KdSettings& s, int maxDepth, float pad) {
  tree.primIds.reserve(2 * prims.size());  // leaves append their slots (straddlers repeat)
  Builder builder(tree, s, maxDepth, pad);
  builder.build(prims, tree.bounds, 0, 0, 0);
  return {builder.depth(), builder.sahSum()};
}

}  // namespace ll::a4::kdbuild
