// The primitives a tree's leaves point at, shared by the BVH, the KD-tree and
// the octree: leaf slot -> primitive id, plus the triangle's vertices copied
// into slot order (the very same floats as the Geometry's, so leaf tests give
// bit-identical t to brute force) and a sphere around the scene for the
// rounding slack of traversal. A KD-tree or octree slot list may name a
// primitive several times (it lies in several cells). Framework code.
#pragma once

#include <cstdint>
#include <vector>

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
  std::vector<LeafTriangle> triangles;  // slot -> vertices, when primIds[slot] is a triangle
  uint32_t triangleCount = 0;           // primitive ids below this are triangles
  Vec3 sceneCentre{0.0f};               // a sphere holding every primitive (world space), for rounding bounds
  float sceneRadius = 0.0f;

  // Appends a slot for primitive `prim` of `geometry` (which must be set).
  void append(uint32_t prim) {
    primIds.push_back(prim);
    LeafTriangle tri{};
    if (prim < triangleCount) {
      const glm::uvec3& t = geometry->triangles[prim];
      tri = {geometry->positions[t.x], geometry->positions[t.y], geometry->positions[t.z]};
    }
    triangles.push_back(tri);
  }

  size_t memoryBytes() const {
    return primIds.capacity() * sizeof(uint32_t) + triangles.capacity() * sizeof(LeafTriangle);
  }
};

}  // namespace ll::a4
