// The bounding volume hierarchy's data: what the build works on (BuildPrim),
// how it splits (SplitSettings), and the flattened tree that traversal reads
// (FlatBvh: an array of 32-byte nodes in depth-first order). Framework code:
// buildBvh() builds a pointer tree with your splitPrimitives() (A4.1) and
// flattens it; your intersectBvh()/occludedBvh() (A4.2) walk the array.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "accel/accelerator.h"
#include "core/math.h"
#include "leaf_primitives.h"
#include "scene/geometry.h"

namespace ll::a4 {

// One primitive as the build sees it: its box and the box's centre (world space).
struct BuildPrim {
  Bounds3 bounds;
  Vec3 centroid{0.0f};
  uint32_t prim = 0;  // id in the Geometry
};

enum class SplitMethod { Median, EqualCounts, Sah };

struct SplitSettings {
  SplitMethod method = SplitMethod::Sah;
  int maxLeaf = 4;                // most primitives per leaf (>= 1)
  int bins = 16;                  // SAH bins per axis
  float traversalCost = 1.0f;     // SAH: cost of entering a node ...
  float intersectionCost = 1.0f;  // ... relative to testing one primitive
};

// Which bounding volume the nodes hold: axis-aligned boxes, or spheres
// (cheaper to store, looser to fit -- the trade-off the lecture shows).
enum class BoundingVolume { Box, Sphere };

// One node of the flattened tree, 32 bytes. Box volume: lo/hi are the box's
// corners. Sphere volume: lo is the centre and hi.x the radius.
// Interior node i: its first child is node i + 1, its second child node
// `offset`; count == 0. Leaf: primitives in slots [offset, offset + count).
struct BvhNode {
  Vec3 lo{0.0f};
  uint32_t offset = 0;
  Vec3 hi{0.0f};
  uint32_t count = 0;
  bool isLeaf() const { return count > 0; }
};
static_assert(sizeof(BvhNode) == 32, "BvhNode is meant to fill half a cache line");

// Deepest tree the build makes; traversal stacks hold this many entries.
constexpr int kBvhMaxDepth = 96;
constexpr int kBvhStackSize = kBvhMaxDepth;

// The leaf slots (LeafPrimitives: geometry, primIds, triangles, ...) hold
// every primitive exactly once.
struct FlatBvh : LeafPrimitives {
  BoundingVolume volume = BoundingVolume::Box;
  std::vector<BvhNode> nodes;  // nodes[0] is the root; empty when there are no primitives
};

// What the build reports (AcceleratorStats without the build time).
struct BvhBuildInfo {
  size_t memoryBytes = 0;
  size_t nodeCount = 0;
  int depth = 0;       // edges on the longest root-to-leaf path
  double sahCost = 0;  // expected cost per ray, traversalCost/intersectionCost units, areas of the volume used
  std::map<std::string, std::string> missingTasks;  // stubs that ran during the build: id -> what
};

// Builds over `geometry` (which must outlive the result). Calls
// splitPrimitives() for every node of two or more primitives.
FlatBvh buildBvh(const Geometry& geometry, const SplitSettings& settings, BoundingVolume volume,
                 BvhBuildInfo* info = nullptr);

// Expected traversal cost of `bvh` under the surface area heuristic.
double sahCost(const FlatBvh& bvh, const SplitSettings& settings);

}  // namespace ll::a4
