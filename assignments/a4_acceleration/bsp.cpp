// Building the BSP tree (framework code): top-down, one plane per node, the
// cheapest under the surface area heuristic among
//   - the planes of up to triangleCandidates of the node's triangles, spread
//     over its list (auto-partition: a mesh's own planes cut it cleanly), and
//   - axisCandidates - 1 evenly spaced axis-aligned planes per axis, plus the
//     faces of the primitives' box (they cut off empty space in one step).
// Each is priced by the areas of the two parts of the cell's bounding box
// and the primitives on each side (binned for axis planes, counted on at most
// kCountSample primitives for triangle planes); the chosen plane then cuts
// the exact convex cell (ConvexCell). A primitive goes to every side it
// comes within `pad` of, so a hit near a plane is in both cells whatever the
// rounding, unless its box misses that side's cell. Written depth-first into
// 24-byte nodes; large nodes build their two subtrees in parallel (oneTBB),
// each into its own arrays, spliced together after (the same tree as one
// thread builds).
#include "bsp.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <string>

#include <tbb/parallel_invoke.h>

#include "bsp_cell.h"
#include "core/phase_progress.h"
#include "kdtree_build_support.h"

namespace ll::a4 {

namespace {

struct Plane {
  Vec3 normal{0.0f};
  float offset = 0.0f;
  bool fromTriangle = false;
  float cost = kInfinity;
  bool found() const { return cost < kInfinity; }
};

// Nodes with more primitives count the sides of each triangle plane on this many, spread over the list.
constexpr size_t kCountSample = 512;
constexpr int kMaxAxisCandidates = 64;

using kdbuild::halfArea;

bool overlaps(const Bounds3& a, const Bounds3& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
         a.min.z <= b.max.z && b.min.z <= a.max.z;
}

// Shared by the builders of one tree (the parallel subtrees'): read-only but the node counter.
struct Shared {
  const BspTree& tree;  // its triangles by primitive id
  const BspSettings& settings;
  int maxDepth;
  float pad;  // world-space distance within which a primitive counts as touching a plane (>> rounding)
  std::vector<Bounds3> boxes;  // by primitive id
  const PhaseSink* sink;       // the calling thread's progress sink (thread-safe), or null
  std::atomic<size_t> nodes{0};
};

// Nodes with at least this many primitives build their subtrees in parallel.
constexpr size_t kParallelPrimitives = 8192;

class Builder {
 public:
  explicit Builder(Shared& shared)
      : sh_(shared), tree_(shared.tree), s_(shared.settings), maxDepth_(shared.maxDepth), pad_(shared.pad),
        boxes_(shared.boxes) {}

  // Appends the subtree of `cell` holding `prims` (consumed) to nodes_ and
  // slots_. depth: edges from the root; splits: of those, the ones with
  // primitives on both sides.
  void build(std::vector<uint32_t>& prims, const ConvexCell& cell, int depth, int splits, int badRefines) {
    const auto index = static_cast<uint32_t>(nodes_.size());
    nodes_.emplace_back();
    // Nodes made by every builder, counted in batches and reported, which is also where a GUI pane's newer
    // request cancels the build (its phase report throws).
    if ((++unreported_ & 0x3FF) == 0) {
      const size_t made = sh_.nodes.fetch_add(unreported_, std::memory_order_relaxed) + unreported_;
      unreported_ = 0;
      if (sh_.sink) (*sh_.sink)("BSP tree build (" + std::to_string(made) + " nodes)", -1.0);
    }
    const size_t made = sh_.nodes.load(std::memory_order_relaxed) + nodes_.size();
    depth_ = std::max(depth_, depth);
    const size_t n = prims.size();
    const float area = cell.area();
    if (n <= static_cast<size_t>(s_.maxLeaf) || splits >= maxDepth_ || depth >= kBspMaxDepth ||
        made + 2 > kBspMaxNodes || !(area > 0.0f))
      return makeLeaf(index, prims, area);
    const Plane plane = bestPlane(prims, cell);
    const float leafCost = s_.intersectionCost * static_cast<float>(n);
    if (!plane.found()) return makeLeaf(index, prims, area);
    if (plane.cost >= leafCost) ++badRefines;  // as the KD-tree: a few uphill splits, none below 16 primitives
    if ((plane.cost >= leafCost && n < 16) || badRefines >= 3) return makeLeaf(index, prims, area);

    ConvexCell cellBelow, cellAbove;
    cell.split(plane.normal, plane.offset, cellBelow, cellAbove);
    // A primitive goes to each side it comes within the pad of, unless its box misses that side's cell.
    Bounds3 boxBelow = cellBelow.bounds(), boxAbove = cellAbove.bounds();
    for (Bounds3* b : {&boxBelow, &boxAbove}) {
      b->min -= Vec3(pad_);
      b->max += Vec3(pad_);
    }
    std::vector<uint32_t> below, above;
    for (const uint32_t p : prims) {
      const auto [lo, hi] = extent(p, plane.normal, plane.offset);
      const bool toBelow = lo < pad_, toAbove = hi > -pad_;
      if (toBelow && toAbove) {  // a straddler: on the sides whose cell's box it reaches
        if (touches(p, boxBelow)) below.push_back(p);
        if (touches(p, boxAbove)) above.push_back(p);
      } else {
        (toBelow ? below : above).push_back(p);
      }
    }
    if ((below.size() == n && above.size() == n) || cellBelow.empty() || cellAbove.empty())
      return makeLeaf(index, prims, area);  // the plane separates nothing
    std::vector<uint32_t>().swap(prims);    // free before recursing
    sah_ += static_cast<double>(s_.traversalCost) * static_cast<double>(area);
    ++(plane.fromTriangle ? trianglePlanes_ : axisPlanes_);
    const int nextSplits = splits + (below.empty() || above.empty() ? 0 : 1);
    if (n >= kParallelPrimitives && !below.empty() && !above.empty()) {
      Builder builderBelow(sh_), builderAbove(sh_);
      tbb::parallel_invoke([&] { builderBelow.build(below, cellBelow, depth + 1, nextSplits, badRefines); },
                           [&] { builderAbove.build(above, cellAbove, depth + 1, nextSplits, badRefines); });
      splice(builderBelow);
      nodes_[index] = BspNode::interior(plane.normal, plane.offset, static_cast<uint32_t>(nodes_.size()));
      splice(builderAbove);
      return;
    }
    build(below, cellBelow, depth + 1, nextSplits, badRefines);
    nodes_[index] = BspNode::interior(plane.normal, plane.offset, static_cast<uint32_t>(nodes_.size()));
    build(above, cellAbove, depth + 1, nextSplits, badRefines);
  }

  int depth() const { return depth_; }
  double sahSum() const { return sah_; }  // sum of cost * area (divide by the root's)
  size_t trianglePlanes() const { return trianglePlanes_; }
  size_t axisPlanes() const { return axisPlanes_; }

  std::vector<BspNode> nodes_;   // subtree in depth-first order; aboveChild indices within it
  std::vector<uint32_t> slots_;  // leaf slots; leaves' first slot within it

 private:
  // Appends a subtree built by another builder, its indices moved to where it lands.
  void splice(const Builder& sub) {
    const auto nodeOffset = static_cast<uint32_t>(nodes_.size()), slotOffset = static_cast<uint32_t>(slots_.size());
    for (BspNode node : sub.nodes_) {
      node.word += node.isLeaf() ? slotOffset : nodeOffset;  // first slot or aboveChild
      nodes_.push_back(node);
    }
    slots_.insert(slots_.end(), sub.slots_.begin(), sub.slots_.end());
    depth_ = std::max(depth_, sub.depth_);
    sah_ += sub.sah_;
    trianglePlanes_ += sub.trianglePlanes_;
    axisPlanes_ += sub.axisPlanes_;
  }

  // The range of dot(normal, x) - offset over primitive p (its vertices, or its box for other kinds).
  std::pair<float, float> extent(uint32_t p, const Vec3& normal, float offset) const {
    if (p < tree_.triangleCount) {
      const LeafTriangle& t = tree_.triangles[p];
      const float d0 = glm::dot(normal, t.p0) - offset, d1 = glm::dot(normal, t.p1) - offset,
                  d2 = glm::dot(normal, t.p2) - offset;
      return {std::min({d0, d1, d2}), std::max({d0, d1, d2})};
    }
    const Bounds3& b = boxes_[p];
    const float c = glm::dot(normal, b.center()) - offset, r = glm::dot(glm::abs(normal), 0.5f * (b.max - b.min));
    return {c - r, c + r};
  }

  // Whether primitive p reaches into `box`: a triangle clipped to it, another kind by its box.
  bool touches(uint32_t p, const Bounds3& box) const {
    if (!overlaps(boxes_[p], box)) return false;
    if (p >= tree_.triangleCount) return true;
    const LeafTriangle& t = tree_.triangles[p];
    return !kdbuild::clippedTriangleBox(t.p0, t.p1, t.p2, box).empty();
  }

  void makeLeaf(uint32_t index, const std::vector<uint32_t>& prims, float area) {
    nodes_[index] = BspNode::leafNode(static_cast<uint32_t>(slots_.size()), static_cast<uint32_t>(prims.size()));
    slots_.insert(slots_.end(), prims.begin(), prims.end());
    sah_ += static_cast<double>(s_.intersectionCost) * static_cast<double>(prims.size()) * static_cast<double>(area);
  }

  // Candidates are priced on the cell's bounding box (its exact convex cell
  // only for the chosen plane): the box cut by an axis plane has a closed
  // form, cut by a triangle's plane it is a 6-face polytope.
  Plane bestPlane(const std::vector<uint32_t>& prims, const ConvexCell& cell) const {
    const size_t n = prims.size();
    const Bounds3 box = cell.bounds();
    const float boxArea = 2.0f * halfArea(box);
    if (!(boxArea > 0.0f)) return {};
    Plane best;
    const auto price = [&](float areaBelow, float areaAbove, float nBelow, float nAbove) {
      return s_.traversalCost + s_.intersectionCost / boxArea * (areaBelow * nBelow + areaAbove * nAbove);
    };
    // Axis-aligned: evenly spaced over the box, counted in bins of the primitives' box faces, and the faces
    // of the primitives' box, which cut off empty space in one step (nothing on one side).
    const int k = std::clamp(s_.axisCandidates, 1, kMaxAxisCandidates);
    Bounds3 primBox;
    for (const uint32_t p : prims) primBox.extend(boxes_[p]);
    for (int a = 0; a < 3; ++a) {
      const float lo = box.min[a], hi = box.max[a];
      if (!(hi - lo > 2.0f * pad_)) continue;
      Vec3 axis(0.0f);
      axis[a] = 1.0f;
      const float scale = static_cast<float>(k) / (hi - lo);
      std::array<uint32_t, kMaxAxisCandidates> starts{}, ends{};
      const auto binOf = [&](float x) {
        const float f = (x - lo) * scale;
        return f >= static_cast<float>(k - 1) ? static_cast<size_t>(k - 1) : f > 0.0f ? static_cast<size_t>(f) : 0;
      };
      for (const uint32_t p : prims) {
        ++starts[binOf(boxes_[p].min[a])];
        ++ends[binOf(boxes_[p].max[a])];
      }
      uint32_t nBelow = 0, nEnded = 0;
      const auto boxAreas = [&](float position, float& below, float& above) {
        Bounds3 b = box, t = box;
        b.max[a] = position;
        t.min[a] = position;
        below = 2.0f * halfArea(b);
        above = 2.0f * halfArea(t);
      };
      for (int i = 1; i < k; ++i) {
        nBelow += starts[static_cast<size_t>(i - 1)];
        nEnded += ends[static_cast<size_t>(i - 1)];
        const float position = lo + (hi - lo) * (static_cast<float>(i) / static_cast<float>(k));
        float areaBelow = 0.0f, areaAbove = 0.0f;
        boxAreas(position, areaBelow, areaAbove);
        const float cost = price(areaBelow, areaAbove, static_cast<float>(nBelow), static_cast<float>(n - nEnded));
        if (cost < best.cost) best = {axis, position, false, cost};
      }
      for (const float position : {primBox.min[a] - pad_, primBox.max[a] + pad_}) {
        if (!(position > lo + pad_ && position < hi - pad_)) continue;
        float areaBelow = 0.0f, areaAbove = 0.0f;
        boxAreas(position, areaBelow, areaAbove);
        const bool allAbove = position < primBox.min[a];
        const float cost = price(areaBelow, areaAbove, allAbove ? 0.0f : static_cast<float>(n),
                                 allAbove ? static_cast<float>(n) : 0.0f);
        if (cost < best.cost) best = {axis, position, false, cost};
      }
    }
    // Auto-partition: the planes of triangles spread over the node's list, counted on a sample.
    const size_t t = std::min(static_cast<size_t>(std::max(s_.triangleCandidates, 0)), n);
    if (t == 0) return best;
    const size_t stride = std::max<size_t>(1, n / kCountSample);
    const float sampleScale = static_cast<float>(n) / static_cast<float>((n + stride - 1) / stride);
    const float cellArea = cell.area();
    std::vector<Vec3> corners;
    for (const auto& f : cell.faces()) corners.insert(corners.end(), f.begin(), f.end());
    for (size_t i = 0; i < t; ++i) {
      const uint32_t p = prims[i * n / t];
      if (p >= tree_.triangleCount) continue;
      const LeafTriangle& tri = tree_.triangles[p];
      const Vec3 c = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
      const float length = glm::length(c);
      if (!(length > 0.0f)) continue;
      const Vec3 normal = c / length;
      const float offset = glm::dot(normal, tri.p0);
      // Only planes that cut the cell by more than the pad on both sides.
      float lo = kInfinity, hi = -kInfinity;
      for (const Vec3& corner : corners) {
        const float d = glm::dot(normal, corner) - offset;
        lo = std::min(lo, d);
        hi = std::max(hi, d);
      }
      if (!(lo < -pad_ && hi > pad_)) continue;
      size_t nBelow = 0, nAbove = 0;
      for (size_t j = 0; j < n; j += stride) {
        const auto [pLo, pHi] = extent(prims[j], normal, offset);
        nBelow += pLo < pad_ ? 1 : 0;
        nAbove += pHi > -pad_ ? 1 : 0;
      }
      float areaBelow = 0.0f, areaAbove = 0.0f;
      cell.splitAreas(normal, offset, areaBelow, areaAbove);
      const float cost = s_.traversalCost + s_.intersectionCost / cellArea * sampleScale *
                                                (areaBelow * static_cast<float>(nBelow) +
                                                 areaAbove * static_cast<float>(nAbove));
      if (cost < best.cost) best = {normal, offset, true, cost};
    }
    return best;
  }

  Shared& sh_;
  const BspTree& tree_;
  const BspSettings& s_;
  int maxDepth_;
  float pad_;
  const std::vector<Bounds3>& boxes_;  // by primitive id
  int depth_ = 0;
  double sah_ = 0.0;
  size_t trianglePlanes_ = 0, axisPlanes_ = 0;
  size_t unreported_ = 0;  // nodes made since the last report
};

}  // namespace

BspTree buildBspTree(const Geometry& geometry, const BspSettings& settings, BspBuildInfo* info) {
  BspTree tree;
  tree.geometry = &geometry;
  tree.triangleCount = geometry.triangleCount();
  const uint32_t n = geometry.primitiveCount();
  BspBuildInfo result;
  if (n > 0) {
    std::vector<uint32_t> prims(n);
    for (uint32_t p = 0; p < n; ++p) {
      prims[p] = p;
      tree.bounds.extend(geometry.bounds(p));
    }
    tree.sceneCentre = tree.bounds.center();
    tree.sceneRadius = 0.5f * tree.bounds.diagonal();
    const int maxDepth = kdbuild::maxSplits(settings.maxDepth, n, kBspMaxDepth);
    tree.storeTrianglesByPrimitive();
    const float pad = kdbuild::roundingPad(tree.bounds);
    // The root cell: the scene's box grown by the pad, so a flat scene still has a volume to cut.
    Bounds3 root = tree.bounds;
    root.min -= Vec3(pad);
    root.max += Vec3(pad);
    const ConvexCell rootCell = ConvexCell::box(root);
    Shared shared{tree, settings, maxDepth, pad, std::vector<Bounds3>(n), currentPhaseSink()};
    for (uint32_t p = 0; p < n; ++p) shared.boxes[p] = geometry.bounds(p);
    Builder builder(shared);
    builder.build(prims, rootCell, 0, 0, 0);
    tree.nodes = std::move(builder.nodes_);
    tree.primIds = std::move(builder.slots_);
    result.depth = builder.depth();
    result.sahCost = builder.sahSum() / static_cast<double>(rootCell.area());
    result.trianglePlanes = builder.trianglePlanes();
    result.axisPlanes = builder.axisPlanes();
    tree.nodes.shrink_to_fit();
    tree.primIds.shrink_to_fit();
  }
  result.nodeCount = tree.nodes.size();
  result.leafSlots = tree.primIds.size();
  result.memoryBytes = tree.nodes.capacity() * sizeof(BspNode) + tree.memoryBytes();
  if (info) *info = result;
  return tree;
}

}  // namespace ll::a4
