#include "scene/geometry.h"

namespace ll {

Bounds3 Geometry::bounds(uint32_t prim) const {
  Bounds3 b;
  if (isTriangle(prim)) {
    const glm::uvec3& tri = triangles[prim];
    b.extend(positions[tri.x]);
    b.extend(positions[tri.y]);
    b.extend(positions[tri.z]);
  } else {
    const Sphere& s = spheres[prim - triangleCount()];
    b.extend(s.center - Vec3(s.radius));
    b.extend(s.center + Vec3(s.radius));
  }
  return b;
}

Bounds3 Geometry::sceneBounds() const {
  Bounds3 b;
  for (uint32_t i = 0; i < primitiveCount(); ++i) b.extend(bounds(i));
  return b;
}

float Geometry::area(uint32_t prim) const {
  if (isTriangle(prim)) {
    const glm::uvec3& tri = triangles[prim];
    return 0.5f * glm::length(glm::cross(positions[tri.y] - positions[tri.x],
                                         positions[tri.z] - positions[tri.x]));
  }
  const float r = spheres[prim - triangleCount()].radius;
  return 4.0f * kPi * r * r;
}

}  // namespace ll
