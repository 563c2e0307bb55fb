// Building the KD-tree (framework code): top-down, one axis-aligned plane per
// node chosen by the surface area heuristic among the bin boundaries of each
// axis of the node's cell; primitives whose box reaches across the plane go
// to both children, where a triangle's box shrinks to the box of the part of
// the triangle inside the child's cell ("perfect splits", Havran; padded for
// rounding). Nodes with at most maxLeaf primitives still take a plane that
// cuts off empty space when that lowers the true SAH cost. Written
// depth-first straight into 8-byte nodes; statistics (nodes, depth, memory,
// SAH cost) on the way.
#include "kdtree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/phase_progress.h"

namespace ll::a4 {

namespace {

// A primitive as one node's build sees it: its box clipped to the node's cell (world space).
struct KdPrim {
  Bounds3 box;
  uint32_t prim = 0;
};

float halfArea(const Bounds3& b) {
  const Vec3 e = glm::max(b.max - b.min, Vec3(0.0f));
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

struct Plane {
  int axis = -1;  // -1: no plane found
  float position = 0.0f;
  float cost = kInfinity;
};

constexpr int kMaxBins = 64;

// The box of the part of triangle (p0, p1, p2) inside `cell` (Sutherland-
// Hodgman against the six planes), or an empty box if there is none.
Bounds3 clippedTriangleBox(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Bounds3& cell) {
  std::array<Vec3, 9> poly{p0, p1, p2}, next{};
  size_t n = 3;
  for (int a = 0; a < 3 && n > 0; ++a)
    for (int side = 0; side < 2 && n > 0; ++side) {
      const float plane = side == 0 ? cell.min[a] : cell.max[a];
      auto inside = [&](const Vec3& v) { return side == 0 ? v[a] >= plane : v[a] <= plane; };
      size_t m = 0;
      for (size_t i = 0; i < n; ++i) {
        const Vec3& u = poly[i];
        const Vec3& v = poly[(i + 1) % n];
        const bool uIn = inside(u), vIn = inside(v);
        if (uIn) next[m++] = u;
        if (uIn != vIn) {
          const float s = (plane - u[a]) / (v[a] - u[a]);
          Vec3 x = u + s * (v - u);
          x[a] = plane;
          next[m++] = x;
        }
      }
      poly = next;
      n = m;
    }
  Bounds3 b;
  for (size_t i = 0; i < n; ++i) b.extend(poly[i]);
  return b;
}

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
    if (plane.cost >= leafCost) ++badRefines;  // PBRT: allow a few uphill splits to get out of local minima
    if ((plane.cost > 4.0f * leafCost && n < 16) || badRefines >= 3) return makeLeaf(index, prims, area);

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
    Bounds3 grown = cell;
    grown.min -= Vec3(pad_);
    grown.max += Vec3(pad_);
    const glm::uvec3& t = tree_.geometry->triangles[p.prim];
    const std::vector<Vec3>& v = tree_.geometry->positions;
    Bounds3 b = clippedTriangleBox(v[t.x], v[t.y], v[t.z], grown);
    if (b.empty()) return;
    b.min = glm::max(b.min - Vec3(pad_), glm::max(p.box.min, cell.min));
    b.max = glm::min(b.max + Vec3(pad_), glm::min(p.box.max, cell.max));
    if (b.empty()) return;
    out.push_back({b, p.prim});
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

KdTree buildKdTree(const Geometry& geometry, const KdSettings& settings, KdBuildInfo* info) {
  KdTree tree;
  tree.geometry = &geometry;
  tree.triangleCount = geometry.triangleCount();
  const uint32_t n = geometry.primitiveCount();
  int depth = 0;
  double sah = 0.0;
  if (n > 0) {
    std::vector<KdPrim> prims(n);
    for (uint32_t p = 0; p < n; ++p) {
      prims[p] = {geometry.bounds(p), p};
      tree.bounds.extend(prims[p].box);
    }
    tree.sceneCentre = tree.bounds.center();
    tree.sceneRadius = 0.5f * tree.bounds.diagonal();
    const int autoDepth = static_cast<int>(std::lround(8.0 + 1.3 * std::log2(static_cast<double>(n))));
    const int maxDepth = std::clamp(settings.maxDepth > 0 ? settings.maxDepth : autoDepth, 0, kKdMaxDepth);
    tree.primIds.reserve(2 * static_cast<size_t>(n));
    tree.storeTrianglesByPrimitive();
    // Clipping rounds by a few ulps of the coordinates: pad by far more.
    const Vec3 far = glm::max(glm::abs(tree.bounds.min), glm::abs(tree.bounds.max));
    const float pad = 1e-5f * (std::max({far.x, far.y, far.z}) + tree.bounds.diagonal());
    Builder builder(tree, settings, maxDepth, pad);
    builder.build(prims, tree.bounds, 0, 0, 0);
    depth = builder.depth();
    const double rootArea = halfArea(tree.bounds);
    sah = rootArea > 0.0 ? builder.sahSum() / rootArea : static_cast<double>(settings.intersectionCost) * n;
    tree.nodes.shrink_to_fit();
    tree.primIds.shrink_to_fit();
    tree.triangles.shrink_to_fit();
  }
  if (info) {
    info->nodeCount = tree.nodes.size();
    info->leafSlots = tree.primIds.size();
    info->depth = depth;
    info->memoryBytes = tree.nodes.capacity() * sizeof(KdNode) + tree.memoryBytes();
    info->sahCost = sah;
  }
  return tree;
}

}  // namespace ll::a4
