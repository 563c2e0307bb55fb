// The tests a tree traversal is made of (BVH, KD-tree, octree), inline
// because they are its inner loop: ray against a node's box or sphere (conservative: they never miss a
// volume whose primitives the ray hits), and ray against the primitive in a
// leaf slot (bit-identical to brute force, ties broken as brute force does).
// Framework code: nothing to edit here.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "bvh.h"
#include "leaf_primitives.h"

namespace ll::a4 {

// Per-ray constants, computed once per query.
struct TraversalRay {
  Ray ray;
  WatertightRay wray;
  Vec3 invDir;             // 1/dir per axis; +-infinity for zero components
  bool negX, negY, negZ;   // dir component < 0 (or -0): the slab's near plane is hi
  float invLength2;        // 1 / |dir|^2
  float tSlack;            // rounding of any t computed in this scene, in t units (see cullLimit)
  TraversalRay(const Ray& r, const LeafPrimitives& bvh)
      : ray(r), wray(r), invDir(1.0f / r.dir.x, 1.0f / r.dir.y, 1.0f / r.dir.z),
        negX(invDir.x < 0.0f), negY(invDir.y < 0.0f), negZ(invDir.z < 0.0f),
        invLength2(1.0f / glm::dot(r.dir, r.dir)),
        tSlack(kSlackUlps * std::numeric_limits<float>::epsilon() *
               (glm::length(r.origin - bvh.sceneCentre) + bvh.sceneRadius) * std::sqrt(invLength2)) {}

  // Below this limit a volume may still hold a hit at distance t. The
  // triangle test's t and a volume's entry distance round differently, by up
  // to a few ulps of the distances involved (origin to geometry), so a node
  // is skipped only when it starts clearly beyond the closest hit.
  float cullLimit(float t) const { return t + tSlack; }

  static constexpr float kSlackUlps = 32.0f;
};

// Rounding slack of the slab test (Ize, "Robust BVH Ray Traversal", JCGT
// 2(2), 2013: 1 + 2 gamma(3)).
constexpr float kBvhRobustScale = 1.0f + 2.0f * 3.0f * (std::numeric_limits<float>::epsilon() * 0.5f);

// Whether the ray meets the box [lo, hi] somewhere in [ray.tmin, tLimit],
// up to rounding: the relative slack covers the slab arithmetic, the absolute
// r.tSlack the plane differences (lo - origin), whose rounding grows with the
// scene's size, not with t -- a flat box (a wall) hit at t ~ 1e-5 by a shadow
// ray leaving the wall is otherwise culled;
// tEntry is where it enters (>= ray.tmin). Axis-parallel rays are exact: a
// zero direction component gives +-infinity, and the NaN of an origin lying
// on a slab plane (0 * infinity) leaves the interval unchanged -- the closed
// slab contains the ray.
inline bool rayEntersBox(const TraversalRay& r, const Vec3& lo, const Vec3& hi, float tLimit, float& tEntry) {
  const Vec3& o = r.ray.origin;
  const float nx = ((r.negX ? hi.x : lo.x) - o.x) * r.invDir.x, fx = ((r.negX ? lo.x : hi.x) - o.x) * r.invDir.x;
  const float ny = ((r.negY ? hi.y : lo.y) - o.y) * r.invDir.y, fy = ((r.negY ? lo.y : hi.y) - o.y) * r.invDir.y;
  const float nz = ((r.negZ ? hi.z : lo.z) - o.z) * r.invDir.z, fz = ((r.negZ ? lo.z : hi.z) - o.z) * r.invDir.z;
  float tn = r.ray.tmin, tf = tLimit;
  tn = nx > tn ? nx : tn;  // written so that a NaN operand keeps tn / tf
  tn = ny > tn ? ny : tn;
  tn = nz > tn ? nz : tn;
  tf = fx < tf ? fx : tf;
  tf = fy < tf ? fy : tf;
  tf = fz < tf ? fz : tf;
  tEntry = tn;
  return tn <= tf * kBvhRobustScale + r.tSlack;
}

// Whether the ray meets the sphere (centre, radius) in [ray.tmin, tLimit];
// tEntry as for boxes. The squared gap between the radius and the ray's
// distance from the centre is padded by its rounding (which grows with the
// distance of the origin).
inline bool rayEntersSphere(const TraversalRay& r, const Vec3& centre, float radius, float tLimit, float& tEntry) {
  const Vec3 oc = centre - r.ray.origin;
  const float tc = glm::dot(oc, r.ray.dir) * r.invLength2;  // closest approach to the centre
  const Vec3 perp = oc - tc * r.ray.dir;
  const float distance = std::abs(oc.x) + std::abs(oc.y) + std::abs(oc.z) + radius;  // >= |oc| + radius
  const float pad = 16.0f * std::numeric_limits<float>::epsilon() * distance * radius;
  const float gap = radius * radius - glm::dot(perp, perp) + pad;
  tEntry = kInfinity;
  if (!(gap >= 0.0f)) return false;
  const float half = std::sqrt(gap * r.invLength2);
  const float tn = std::max(tc - half, r.ray.tmin);
  const float tf = std::min(tc + half, tLimit);
  tEntry = tn;
  return tn <= tf * kBvhRobustScale + r.tSlack;
}

// The next float above t (t finite or infinite, not NaN).
inline float nextFloatUp(float t) {
  if (t == kInfinity) return t;
  if (t == 0.0f) return std::numeric_limits<float>::denorm_min();
  const uint32_t bits = std::bit_cast<uint32_t>(t);
  return std::bit_cast<float>(t > 0.0f ? bits + 1 : bits - 1);
}

// Tests the primitive in leaf slot `slot` and keeps in `hit` what brute force
// would keep: the smallest t in (ray.tmin, ray.tmax), on equal t the smaller
// primitive id. Start with hit = Hit{} and hit.t = ray.tmax. Returns whether
// `hit` changed.
inline bool closerPrimitiveHit(const LeafPrimitives& bvh, uint32_t slot, const TraversalRay& r, Hit& hit) {
  const uint32_t prim = bvh.primIds[slot];
  const float tmax = (hit.prim != Hit::kNone && prim < hit.prim) ? nextFloatUp(hit.t) : hit.t;
  float t, b1 = 0.0f, b2 = 0.0f;
  if (prim < bvh.triangleCount) {
    const LeafTriangle& tri = bvh.triangle(slot, prim);
    if (!intersectTriangle(r.wray, tri.p0, tri.p1, tri.p2, r.ray.tmin, tmax, t, b1, b2)) return false;
  } else {
    const Sphere& s = bvh.geometry->spheres[prim - bvh.triangleCount];
    if (!intersectSphere(r.ray, s.center, s.radius, r.ray.tmin, tmax, t)) return false;
  }
  hit.t = t;
  hit.prim = prim;
  hit.b1 = b1;
  hit.b2 = b2;
  return true;
}

// Whether the primitive in leaf slot `slot` is hit with ray.tmin < t < ray.tmax.
inline bool anyPrimitiveHit(const LeafPrimitives& bvh, uint32_t slot, const TraversalRay& r) {
  const uint32_t prim = bvh.primIds[slot];
  float t, b1, b2;
  if (prim < bvh.triangleCount) {
    const LeafTriangle& tri = bvh.triangle(slot, prim);
    return intersectTriangle(r.wray, tri.p0, tri.p1, tri.p2, r.ray.tmin, r.ray.tmax, t, b1, b2);
  }
  const Sphere& s = bvh.geometry->spheres[prim - bvh.triangleCount];
  return intersectSphere(r.ray, s.center, s.radius, r.ray.tmin, r.ray.tmax, t);
}

}  // namespace ll::a4
