// The KD-tree's data: build settings, the flattened tree of 8-byte nodes that
// traversal (A4.3) reads, and the build. A KD-tree splits space, not the
// primitives: a node's cell is cut by one axis-aligned plane, and a primitive
// whose box reaches across the plane is referenced by both children (leaf
// slots may repeat a primitive). Framework code: buildKdTree() chooses every
// plane by the surface area heuristic, over every candidate plane with sorted
// event lists (Wald and Havran 2006), or over binned candidates.
#pragma once

#include <bit>
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "leaf_primitives.h"
#include "scene/geometry.h"

namespace ll::a4 {

// How the build finds each node's plane. Sweep: every face of every box is a
// candidate, swept in sorted order (Wald and Havran 2006, O(n log n) for the
// tree); binned: `bins` - 1 evenly spaced candidates per axis plus the faces
// of the primitives' box, counted in bins at every node.
enum class KdBuild { Sweep, Binned };

struct KdSettings {
  KdBuild build = KdBuild::Sweep;
  int maxDepth = 0;  // most splits above a leaf, not counting empty-space cuts; 0 = 8 + 1.3 log2(n), PBRT's rule
  int maxLeaf = 2;                // nodes with at most this many primitives become leaves, unless
                                  // cutting off empty space lowers their SAH cost
  float traversalCost = 1.0f;     // SAH: cost of one traversal step ...
  float intersectionCost = 1.5f;  // ... relative to one primitive test
  float emptyBonus = 0.5f;        // SAH: a split with an empty side costs (1 - emptyBonus) times as much
  int bins = 32;                  // bins per axis: bins - 1 evenly spaced candidate planes (the binned
                                  // build's; the sweep also offers them between faces)
};

// Deepest tree the build makes (empty-space cuts included); traversal stacks
// hold this many entries.
constexpr int kKdMaxDepth = 64;
constexpr int kKdStackSize = kKdMaxDepth;
// Most nodes a tree may have (aboveChild has 28 bits); the build makes leaves beyond.
constexpr size_t kKdMaxNodes = size_t{1} << 28;

// One node, 8 bytes. Interior: cut along axis() at split(); the child below
// the plane (coordinate <= split) is the next node, the child above it node
// aboveChild(); belowEmpty() / aboveEmpty() say that child is a leaf without
// primitives, so a traversal may skip it without loading it (it need not:
// the empty leaves are there). Leaf: primitives in slots [first(), first() +
// count()). Cells are closed boxes: both children include the plane.
struct KdNode {
  uint32_t word = 0;  // interior: the split plane's bits; leaf: first slot
  uint32_t bits = 0;  // low 2 bits: axis 0-2, or 3 for a leaf. Interior: bit 2 below empty, bit 3 above
                      // empty, the rest aboveChild; leaf: the rest count

  static KdNode interior(int axis, float split, uint32_t aboveChild, bool belowEmpty, bool aboveEmpty) {
    return {std::bit_cast<uint32_t>(split), (aboveChild << 4) | (aboveEmpty ? 8u : 0u) | (belowEmpty ? 4u : 0u) |
                                                static_cast<uint32_t>(axis)};
  }
  static KdNode leafNode(uint32_t first, uint32_t count) { return {first, (count << 2) | 3u}; }
  bool isLeaf() const { return (bits & 3u) == 3u; }
  int axis() const { return static_cast<int>(bits & 3u); }
  float split() const { return std::bit_cast<float>(word); }
  uint32_t aboveChild() const { return bits >> 4; }
  bool belowEmpty() const { return (bits & 4u) != 0; }
  bool aboveEmpty() const { return (bits & 8u) != 0; }
  uint32_t first() const { return word; }
  uint32_t count() const { return bits >> 2; }
};
static_assert(sizeof(KdNode) == 8);

// The tree: nodes in depth-first order (below child first), the root's cell
// `bounds` (the scene's box), and the leaf slots.
struct KdTree : LeafPrimitives {
  Bounds3 bounds;
  std::vector<KdNode> nodes;  // nodes[0] is the root; empty when there are no primitives
};

struct KdBuildInfo {
  size_t memoryBytes = 0;
  size_t nodeCount = 0;
  size_t leafSlots = 0;  // primitive references in leaves (>= primitives: straddlers repeat)
  int depth = 0;
  double sahCost = 0.0;  // expected cost per ray through the root, traversalCost/intersectionCost units
};

// Builds over `geometry` (which must outlive the result).
KdTree buildKdTree(const Geometry& geometry, const KdSettings& settings, KdBuildInfo* info = nullptr);

}  // namespace ll::a4
