// The primitives a tree's leaves point at, shared by the BVH, the KD-tree and
// the octree: leaf slot -> primitive id, plus the triangles' vertices (the
// very same floats as the Geometry's, so leaf tests give bit-identical t to
// brute force) and a sphere around the scene for the rounding slack of
// traversal. The BVH names each primitive once and copies the vertices in
// slot order (a leaf's triangles sit side by side in memory). A KD-tree or
// octree names a primitive in every cell it touches -- about ten times on a
// fine mesh -- so there the vertices are stored once per primitive and slots
// only hold ids (a quarter of the memory, and fewer cache misses). Framework code.
#pragma once

#include <cstdint>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/huge_pages.h"
#include "core/math.h"
#include "scene/geometry.h"

namespace ll::a4 {

// A triangle's vertices (world space).
struct LeafTriangle {
  Vec3 p0, p1, p2;
};

struct LeafPrimitives {
  const Geometry* geometry = nullptr;
  std::vector<uint32_t> primIds;        // slot -> primitive id in the Geometry
  std::vector<LeafTriangle> triangles;  // vertices by slot, or by primitive id (byPrimitive)
  bool byPrimitive = false;             // triangles are indexed by primitive id, not by slot
  uint32_t triangleCount = 0;           // primitive ids below this are triangles
  Vec3 sceneCentre{0.0f};               // a sphere holding every primitive (world space), for rounding bounds
  float sceneRadius = 0.0f;

  // The vertices of triangle `prim`, named in leaf slot `slot`.
  const LeafTriangle& triangle(uint32_t slot, uint32_t prim) const { return triangles[byPrimitive ? prim : slot]; }

  // Space partitions: one copy of every triangle's vertices, indexed by
  // primitive id (`geometry` must be set); slots are then appended as ids.
  void storeTrianglesByPrimitive() {
    byPrimitive = true;
    resizeOnHugePages(triangles, triangleCount);
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, triangleCount, 16384), [&](const tbb::blocked_range<uint32_t>& r) {
      for (uint32_t prim = r.begin(); prim < r.end(); ++prim) {
        const glm::uvec3& t = geometry->triangles[prim];
        triangles[prim] = {geometry->positions[t.x], geometry->positions[t.y], geometry->positions[t.z]};
      }
    });
  }

  size_t memoryBytes() const {
    return primIds.capacity() * sizeof(uint32_t) + triangles.capacity() * sizeof(LeafTriangle);
  }
};

}  // namespace ll::a4
