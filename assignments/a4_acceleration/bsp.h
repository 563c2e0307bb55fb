// The BSP tree's data: build settings, the flattened tree of 24-byte nodes
// that traversal (A4.5) reads, and the build. A binary space partition cuts
// space like the KD-tree, but by planes of any orientation: the planes of the
// scene's own triangles ("auto-partition") as well as axis-aligned ones, each
// chosen by the surface area heuristic over the convex cells it makes (Ize,
// Wald and Parker, "Ray tracing with the BSP tree", IEEE Symposium on
// Interactive Ray Tracing 2008). A primitive touching both sides of a plane
// (within a small distance, for rounding) is referenced by both children.
// Framework code: buildBspTree().
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"
#include "leaf_primitives.h"
#include "scene/geometry.h"

namespace ll::a4 {

struct BspSettings {
  int maxDepth = 0;               // most splits above a leaf; 0 = 8 + 1.3 log2(n), as the KD-tree
  int maxLeaf = 2;                // nodes with at most this many primitives become leaves
  float traversalCost = 1.0f;     // SAH: cost of one traversal step (a plane test) ...
  float intersectionCost = 1.5f;  // ... relative to one primitive test
  int triangleCandidates = 2;    // planes of this many of the node's triangles are candidates (auto-partition) ...
  int axisCandidates = 32;        // ... and, per axis, this many - 1 evenly spaced axis-aligned planes
};

// Deepest tree the build makes; traversal stacks hold this many entries.
constexpr int kBspMaxDepth = 64;
constexpr int kBspStackSize = kBspMaxDepth;
constexpr size_t kBspMaxNodes = size_t{1} << 30;

// One node, 24 bytes. Interior: the plane dot(normal, x) = offset (normal of
// unit length, world space); the child below it (dot < offset) is the next
// node, the child above it node aboveChild(). Leaf: primitives in slots
// [first(), first() + count()). Cells are closed: both children include the plane.
struct BspNode {
  static constexpr int kAnyPlane = 3;  // axis() of a plane not perpendicular to an axis

  Vec3 normal{0.0f};
  float offset = 0.0f;
  uint32_t word = 0;  // interior: aboveChild; leaf: first slot
  uint32_t bits = 0;  // bit 0: leaf; the rest: leaf, count; interior, axis()

  static BspNode interior(const Vec3& normal, float offset, uint32_t aboveChild) {
    uint32_t axis = kAnyPlane;
    for (int a = 0; a < 3; ++a)
      if (normal[a] == 1.0f && normal[(a + 1) % 3] == 0.0f && normal[(a + 2) % 3] == 0.0f) axis = static_cast<uint32_t>(a);
    return {normal, offset, aboveChild, axis << 1};
  }
  static BspNode leafNode(uint32_t first, uint32_t count) { return {Vec3(0.0f), 0.0f, first, (count << 1) | 1u}; }
  bool isLeaf() const { return (bits & 1u) != 0; }
  // Interior: the axis a whose plane x[a] = offset this is (normal the unit vector along a), or kAnyPlane.
  // Such a plane's crossing is the KD-tree's, (offset - origin[a]) / dir[a]: no dot products.
  int axis() const { return static_cast<int>(bits >> 1); }
  uint32_t aboveChild() const { return word; }
  uint32_t first() const { return word; }
  uint32_t count() const { return bits >> 1; }
};
static_assert(sizeof(BspNode) == 24);

// The tree: nodes in depth-first order (below child first), the root's cell
// `bounds` (the scene's box), and the leaf slots (vertices by primitive, as
// the KD-tree's).
struct BspTree : LeafPrimitives {
  Bounds3 bounds;
  std::vector<BspNode> nodes;  // nodes[0] is the root; empty when there are no primitives
};

struct BspBuildInfo {
  size_t memoryBytes = 0;
  size_t nodeCount = 0;
  size_t leafSlots = 0;         // primitive references in leaves (>= primitives)
  size_t trianglePlanes = 0;    // interior nodes cut by a triangle's plane (auto-partition) ...
  size_t axisPlanes = 0;        // ... and by an axis-aligned plane
  int depth = 0;
  double sahCost = 0.0;  // expected cost per ray through the root, traversalCost/intersectionCost units
};

// Builds over `geometry` (which must outlive the result).
BspTree buildBspTree(const Geometry& geometry, const BspSettings& settings, BspBuildInfo* info = nullptr);

}  // namespace ll::a4
