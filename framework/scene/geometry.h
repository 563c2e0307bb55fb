// All of a scene's primitives in world space, in one flat list that
// accelerators index: primitive ids [0, triangleCount) are triangles, then
// come the spheres. Accelerators only need bounds(), centroid() and
// intersect(); the rest serves shading.
#pragma once

#include <cstdint>
#include <vector>

#include "accel/ray_sphere.h"
#include "accel/ray_triangle.h"
#include "core/math.h"
#include "core/ray.h"

namespace ll {

struct Sphere {
  Vec3 center{0.0f};
  float radius = 1.0f;
};

class Geometry {
 public:
  // Per-vertex data (world space). normals/uvs are empty or match positions.
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
  std::vector<Vec2> uvs;
  std::vector<glm::uvec3> triangles;       // vertex indices
  std::vector<uint32_t> triangleObject;    // owning object per triangle
  std::vector<Sphere> spheres;
  std::vector<uint32_t> sphereObject;      // owning object per sphere

  uint32_t triangleCount() const { return static_cast<uint32_t>(triangles.size()); }
  uint32_t primitiveCount() const { return static_cast<uint32_t>(triangles.size() + spheres.size()); }
  bool isTriangle(uint32_t prim) const { return prim < triangles.size(); }
  uint32_t objectOf(uint32_t prim) const {
    return isTriangle(prim) ? triangleObject[prim] : sphereObject[prim - triangleCount()];
  }

  Bounds3 bounds(uint32_t prim) const;
  Vec3 centroid(uint32_t prim) const { return bounds(prim).center(); }
  Bounds3 sceneBounds() const;
  float area(uint32_t prim) const;

  // Reference primitive test (watertight triangles, careful spheres): on a hit
  // with ray.tmin < t < hit.t, updates hit and returns true.
  bool intersect(uint32_t prim, const Ray& ray, const WatertightRay& wray, Hit& hit) const {
    float t, b1 = 0.0f, b2 = 0.0f;
    if (isTriangle(prim)) {
      const glm::uvec3& tri = triangles[prim];
      if (!intersectTriangle(wray, positions[tri.x], positions[tri.y], positions[tri.z], ray.tmin,
                             hit.t, t, b1, b2))
        return false;
    } else {
      const Sphere& s = spheres[prim - triangleCount()];
      if (!intersectSphere(ray, s.center, s.radius, ray.tmin, hit.t, t)) return false;
    }
    hit.t = t;
    hit.prim = prim;
    hit.b1 = b1;
    hit.b2 = b2;
    return true;
  }
};

}  // namespace ll
