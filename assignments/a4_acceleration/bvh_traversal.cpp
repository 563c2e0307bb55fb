// A4.2 BVH traversal: closest hit and any hit.
#include "a4_tasks.h"
#include "bvh_ray_tests.h"
#include "render/student_task.h"

namespace ll::a4 {

#if LIGHTLAB_SOLUTION  // A4.2 (helpers)
namespace {

struct StackEntry {
  uint32_t node;
  float tEntry;  // where the ray enters the node's volume
};

template <BoundingVolume V>
inline bool enters(const TraversalRay& r, const BvhNode& n, float tLimit, float& tEntry) {
  if constexpr (V == BoundingVolume::Box)
    return rayEntersBox(r, n.lo, n.hi, tLimit, tEntry);
  else
    return rayEntersSphere(r, n.lo, n.hi.x, tLimit, tEntry);
}

// Depth first, nearer child first. AnyHit: return at the first primitive hit.
// hit.t must start at ray.tmax.
template <BoundingVolume V, bool AnyHit>
bool traverse(const FlatBvh& bvh, const TraversalRay& r, Hit& hit, QueryCounters& counters) {
  const BvhNode* nodes = bvh.nodes.data();
  float tLimit = r.cullLimit(hit.t);
  float tEntry;
  if (!enters<V>(r, nodes[0], tLimit, tEntry)) return false;
  StackEntry stack[kBvhStackSize];
  int sp = 0;
  uint32_t current = 0;
  uint64_t visited = 0, tested = 0;
  bool found = false;
  for (;;) {
    ++visited;
    const BvhNode& node = nodes[current];
    if (node.isLeaf()) {
      tested += node.count;
      for (uint32_t s = node.offset, end = node.offset + node.count; s < end; ++s) {
        if constexpr (AnyHit) {
          if (anyPrimitiveHit(bvh, s, r)) {
            found = true;
            break;
          }
        } else if (closerPrimitiveHit(bvh, s, r, hit)) {
          found = true;
          tLimit = r.cullLimit(hit.t);
        }
      }
      if (AnyHit && found) break;
    } else {
      const uint32_t a = current + 1, b = node.offset;
      float ta, tb;
      const bool hitA = enters<V>(r, nodes[a], tLimit, ta);
      const bool hitB = enters<V>(r, nodes[b], tLimit, tb);
      // The far child of a node entered is the next cache miss: start loading it now.
      if (hitA && !nodes[a].isLeaf()) __builtin_prefetch(&nodes[nodes[a].offset]);
      if (hitB && !nodes[b].isLeaf()) __builtin_prefetch(&nodes[nodes[b].offset]);
      if (hitA && hitB) {
        if (tb < ta) {
          stack[sp++] = {a, ta};
          current = b;
        } else {
          stack[sp++] = {b, tb};
          current = a;
        }
        continue;
      }
      if (hitA || hitB) {
        current = hitA ? a : b;
        continue;
      }
    }
    // Pop the nearest postponed node that may still hold a closer hit.
    while (sp > 0 && !(stack[sp - 1].tEntry <= tLimit)) --sp;
    if (sp == 0) break;
    current = stack[--sp].node;
  }
  counters.nodesVisited += visited;
  counters.primitivesTested += tested;
  return found;
}

}  // namespace
#endif

bool intersectBvh(const FlatBvh& bvh, const Ray& ray, Hit& hit, QueryCounters& counters) {
  hit = Hit{};
  hit.t = ray.tmax;
  const TraversalRay r(ray, bvh);
#if LIGHTLAB_SOLUTION  // A4.2
  if (bvh.nodes.empty()) return false;
  return bvh.volume == BoundingVolume::Box ? traverse<BoundingVolume::Box, false>(bvh, r, hit, counters)
                                           : traverse<BoundingVolume::Sphere, false>(bvh, r, hit, counters);
#else
  // Your A4.2 here (see its comment in a4_tasks.h), then delete the line below.
  (void)bvh;
  (void)r;
  (void)hit;
  (void)counters;
  LIGHTLAB_TODO_EXACT("A4.2", "BVH traversal (assignments/a4_acceleration/bvh_traversal.cpp)");
  return false;
#endif
}

bool occludedBvh(const FlatBvh& bvh, const Ray& ray, QueryCounters& counters) {
  const TraversalRay r(ray, bvh);
  Hit hit;  // for the leaf tests: anything closer than tmax
  hit.t = ray.tmax;
#if LIGHTLAB_SOLUTION  // A4.2
  if (bvh.nodes.empty()) return false;
  return bvh.volume == BoundingVolume::Box ? traverse<BoundingVolume::Box, true>(bvh, r, hit, counters)
                                           : traverse<BoundingVolume::Sphere, true>(bvh, r, hit, counters);
#else
  // Your A4.2 here (see its comment in a4_tasks.h), then delete the line below.
  (void)bvh;
  (void)r;
  (void)hit;
  (void)counters;
  LIGHTLAB_TODO_EXACT("A4.2", "BVH traversal (assignments/a4_acceleration/bvh_traversal.cpp)");
  return false;
#endif
}

}  // namespace ll::a4
