// The Accelerator interface: built once over a scene's primitives, it answers
// closest-hit and any-hit queries. Every implementation must return the same
// closest hit (t and primitive) as brute force on any ray.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/math.h"
#include "core/params.h"
#include "core/ray.h"
#include "scene/geometry.h"

namespace ll {

// Per-query work, accumulated by the caller (one instance per thread or tile).
struct QueryCounters {
  uint64_t nodesVisited = 0;
  uint64_t primitivesTested = 0;
  void add(const QueryCounters& o) {
    nodesVisited += o.nodesVisited;
    primitivesTested += o.primitivesTested;
  }
};

struct AcceleratorStats {
  double buildSeconds = 0.0;
  size_t memoryBytes = 0;  // of the structure itself, not the geometry
  size_t nodeCount = 0;
  int depth = 0;
  double sahCost = 0.0;  // expected cost per ray under the surface area heuristic (0 = not reported)
};

// One node of a structure as the GUI draws it: a box (BVH box, KD-tree or
// octree cell) or a sphere (BVH with bounding spheres). World space.
struct NodeShape {
  Bounds3 box;
  bool isSphere = false;
  Vec3 center{0.0f};
  float radius = 0.0f;
  bool leaf = false;
  std::vector<std::pair<Vec3, Vec3>> edges;  // a convex cell (BSP tree): drawn instead of the box when given
};

// The statistics of a tree whose build reports memoryBytes, nodeCount, depth and sahCost.
template <class BuildInfo>
AcceleratorStats treeStats(double buildSeconds, const BuildInfo& info) {
  AcceleratorStats s;
  s.buildSeconds = buildSeconds;
  s.memoryBytes = info.memoryBytes;
  s.nodeCount = info.nodeCount;
  s.depth = info.depth;
  s.sahCost = info.sahCost;
  return s;
}

class Accelerator {
 public:
  virtual ~Accelerator() = default;
  // Builds over `geometry`, which must outlive the accelerator.
  virtual void build(const Geometry& geometry) = 0;
  // Closest hit with ray.tmin < t < ray.tmax; on success fills hit and returns true.
  virtual bool intersect(const Ray& ray, Hit& hit, QueryCounters& counters) const = 0;
  // Whether anything is hit with ray.tmin < t < ray.tmax (may stop at the first).
  virtual bool occluded(const Ray& ray, QueryCounters& counters) const = 0;
  virtual AcceleratorStats stats() const = 0;
  // True for brute force (`none`), which has no structure: every query tests every primitive.
  virtual bool testsEveryPrimitive() const { return false; }
  // The nodes at `depth` (root = 0), plus leaves that end above it, for the
  // GUI's structure overlay. Default: nothing to draw (brute force, Embree).
  virtual std::vector<NodeShape> nodesAtDepth(int depth) const {
    (void)depth;
    return {};
  }
};

// What the registry knows about an accelerator: its name, help, parameters
// and a factory. One per implementation file.
struct AcceleratorInfo {
  std::string name;
  std::string help;
  std::vector<ParamDecl> params;
  std::unique_ptr<Accelerator> (*make)(const ParamSet& params) = nullptr;
};

}  // namespace ll
