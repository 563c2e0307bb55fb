// Building the octree (framework code): the root is a cube around the scene;
// a cell with more than maxLeaf primitives (and above maxDepth) is cut into
// eight, and each primitive goes to every child its box touches -- unless
// that separates nothing. Statistics on the way.
#include "octree.h"

#include <algorithm>
#include <array>

namespace ll::a4 {

namespace {

bool overlaps(const Bounds3& b, const Vec3& lo, const Vec3& hi) {  // closed boxes
  return b.min.x <= hi.x && b.max.x >= lo.x && b.min.y <= hi.y && b.max.y >= lo.y && b.min.z <= hi.z &&
         b.max.z >= lo.z;
}

float halfArea(const Vec3& lo, const Vec3& hi) {
  const Vec3 e = glm::max(hi - lo, Vec3(0.0f));
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

class Builder {
 public:
  Builder(Octree& tree, const std::vector<Bounds3>& boxes, const OctreeSettings& s)
      : tree_(tree), boxes_(boxes), s_(s) {}

  // Fills node `index` (already allocated) for the cell [lo, hi] holding `prims` (consumed).
  void build(uint32_t index, std::vector<uint32_t>& prims, const Vec3& lo, const Vec3& hi, int depth) {
    depth_ = std::max(depth_, depth);
    const double area = halfArea(lo, hi);
    const size_t n = prims.size();
    if (n > static_cast<size_t>(s_.maxLeaf) && depth < s_.maxDepth) {
      std::array<std::vector<uint32_t>, 8> children;
      std::array<Vec3, 8> childLo, childHi;
      size_t separated = 0, nonEmpty = 0, references = 0;
      for (int i = 0; i < 8; ++i) {
        const auto ci = static_cast<size_t>(i);
        octreeChildCell(lo, hi, i, childLo[ci], childHi[ci]);
        for (uint32_t p : prims)
          if (overlaps(boxes_[p], childLo[ci], childHi[ci])) children[ci].push_back(p);
        const size_t m = children[ci].size();
        nonEmpty += m > 0 ? 1 : 0;
        separated += (m > 0 && m < n) ? 1 : 0;
        references += m;
      }
      // Worth it if some child holds only part of the primitives, or one child
      // holds them all (the cell shrinks around them); not if the non-empty
      // children all hold everything (identical or mutually overlapping
      // primitives), nor if most primitives are bigger than the children
      // (over 4 references each on average: splitting would only copy them).
      const bool progress = (separated > 0 || nonEmpty == 1) && references <= 4 * n;
      if (progress) {
        std::vector<uint32_t>().swap(prims);
        const auto first = static_cast<uint32_t>(tree_.nodes.size());
        tree_.nodes.resize(tree_.nodes.size() + 8);
        tree_.nodes[index] = {first, OctreeNode::kInterior};
        sah_ += area;
        for (uint32_t i = 0; i < 8; ++i) build(first + i, children[i], childLo[i], childHi[i], depth + 1);
        return;
      }
    }
    tree_.nodes[index] = {static_cast<uint32_t>(tree_.primIds.size()), static_cast<uint32_t>(n)};
    for (uint32_t p : prims) tree_.primIds.push_back(p);
    sah_ += static_cast<double>(n) * area;
  }

  int depth() const { return depth_; }
  double sahSum() const { return sah_; }

 private:
  Octree& tree_;
  const std::vector<Bounds3>& boxes_;
  const OctreeSettings& s_;
  int depth_ = 0;
  double sah_ = 0.0;
};

}  // namespace

Octree buildOctree(const Geometry& geometry, const OctreeSettings& settings, OctreeBuildInfo* info) {
  Octree tree;
  tree.geometry = &geometry;
  tree.triangleCount = geometry.triangleCount();
  const uint32_t n = geometry.primitiveCount();
  int depth = 0;
  double sah = 0.0;
  if (n > 0) {
    std::vector<Bounds3> boxes(n);
    Bounds3 scene;
    std::vector<uint32_t> prims(n);
    for (uint32_t p = 0; p < n; ++p) {
      boxes[p] = geometry.bounds(p);
      scene.extend(boxes[p]);
      prims[p] = p;
    }
    // A cube around the scene (rounded outward so that it holds the scene's box).
    const Vec3 c = scene.center();
    const Vec3 e = scene.extent();
    const float half = 0.5f * std::max({e.x, e.y, e.z});
    tree.bounds.min = glm::min(c - Vec3(half), scene.min);
    tree.bounds.max = glm::max(c + Vec3(half), scene.max);
    tree.sceneCentre = scene.center();
    tree.sceneRadius = 0.5f * scene.diagonal();
    OctreeSettings s = settings;
    s.maxDepth = std::clamp(s.maxDepth, 0, kOctreeMaxDepth);
    s.maxLeaf = std::max(s.maxLeaf, 1);
    tree.storeTrianglesByPrimitive();
    tree.nodes.emplace_back();
    Builder builder(tree, boxes, s);
    builder.build(0, prims, tree.bounds.min, tree.bounds.max, 0);
    depth = builder.depth();
    const double rootArea = halfArea(tree.bounds.min, tree.bounds.max);
    sah = rootArea > 0.0 ? builder.sahSum() / rootArea : static_cast<double>(n);
    tree.nodes.shrink_to_fit();
    tree.primIds.shrink_to_fit();
    tree.triangles.shrink_to_fit();
  }
  if (info) {
    info->nodeCount = tree.nodes.size();
    info->leafSlots = tree.primIds.size();
    info->depth = depth;
    info->memoryBytes = tree.nodes.capacity() * sizeof(OctreeNode) + tree.memoryBytes();
    info->sahCost = sah;
  }
  return tree;
}

}  // namespace ll::a4
