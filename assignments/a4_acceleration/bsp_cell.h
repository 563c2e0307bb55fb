// A cell of a BSP tree: a convex polyhedron, stored as its faces (convex
// polygons, vertices counter-clockwise seen from outside). The build cuts
// cells by arbitrary planes and prices each cut by the surface areas of the
// two parts (the SAH); the GUI draws their edges. Framework code.
#pragma once

#include <utility>
#include <vector>

#include "core/math.h"

namespace ll::a4 {

class ConvexCell {
 public:
  ConvexCell() = default;
  static ConvexCell box(const Bounds3& b);  // b must not be empty

  bool empty() const { return faces_.empty(); }
  const std::vector<std::vector<Vec3>>& faces() const { return faces_; }
  float area() const;  // surface area (world units^2)
  Bounds3 bounds() const;

  // The surface areas of the parts with dot(normal, x) <= offset (below) and
  // >= offset (above), without making them: each face is clipped in place
  // and the cut's own area follows from the closed surface's vector area
  // summing to zero. Allocation-free; for pricing many candidate planes.
  void splitAreas(const Vec3& normal, float offset, float& below, float& above) const;

  // The two parts (either may be empty when the plane misses the cell).
  void split(const Vec3& normal, float offset, ConvexCell& below, ConvexCell& above) const;

  // Every edge once, for drawing.
  std::vector<std::pair<Vec3, Vec3>> edges() const;

 private:
  std::vector<std::vector<Vec3>> faces_;
};

}  // namespace ll::a4
