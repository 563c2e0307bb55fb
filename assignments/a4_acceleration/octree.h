// The octree's data: build settings, the flattened tree of 8-byte nodes that
// traversal (A4.4) reads, and the build. Every interior cell is cut at its
// centre into eight equal children; a primitive whose box touches several
// children (closed boxes) is referenced by each of them, so leaf slots may
// repeat a primitive. Framework code.
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"
#include "leaf_primitives.h"
#include "scene/geometry.h"

namespace ll::a4 {

struct OctreeSettings {
  int maxDepth = 14;  // deepest leaf (edges from the root), <= kOctreeMaxDepth
  int maxLeaf = 8;    // cells with at most this many primitives are not subdivided
};

constexpr int kOctreeMaxDepth = 16;
// Traversal pushes at most 7 siblings per level.
constexpr int kOctreeStackSize = 7 * kOctreeMaxDepth + 1;

// One node, 8 bytes. Interior (count == kInterior): its children are nodes
// [offset, offset + 8); child i holds the upper half of the cell along x if
// bit 0 of i is set, along y if bit 1, along z if bit 2. Leaf: primitives in
// slots [offset, offset + count) (count may be 0: an empty cell).
struct OctreeNode {
  static constexpr uint32_t kInterior = 0xffffffffu;
  uint32_t offset = 0;
  uint32_t count = 0;
  bool isLeaf() const { return count != kInterior; }
};
static_assert(sizeof(OctreeNode) == 8);

// Child `i`'s cell of the cell [lo, hi] (world space), the same floats in
// build and traversal.
inline Vec3 octreeCentre(const Vec3& lo, const Vec3& hi) { return 0.5f * (lo + hi); }
inline void octreeChildCell(const Vec3& lo, const Vec3& hi, int i, Vec3& childLo, Vec3& childHi) {
  const Vec3 c = octreeCentre(lo, hi);
  for (int a = 0; a < 3; ++a) {
    const bool upper = (i >> a) & 1;
    childLo[a] = upper ? c[a] : lo[a];
    childHi[a] = upper ? hi[a] : c[a];
  }
}

// The tree: nodes (root first, the eight children of a node contiguous), the
// root's cell `bounds` (a cube around the scene) and the leaf slots.
struct Octree : LeafPrimitives {
  Bounds3 bounds;
  std::vector<OctreeNode> nodes;  // empty when there are no primitives
};

struct OctreeBuildInfo {
  size_t memoryBytes = 0;
  size_t nodeCount = 0;
  size_t leafSlots = 0;  // primitive references in leaves (>= primitives: straddlers repeat)
  int depth = 0;
  double sahCost = 0.0;  // expected cost per ray through the root (1 per node entered, 1 per primitive tested)
};

// Builds over `geometry` (which must outlive the result).
Octree buildOctree(const Geometry& geometry, const OctreeSettings& settings, OctreeBuildInfo* info = nullptr);

}  // namespace ll::a4
