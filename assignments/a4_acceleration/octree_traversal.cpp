// A4.4 Octree traversal: closest hit (children in the order the ray enters
// them, early exit once the closest hit lies in the current cell) and any hit.
#include "a4_tasks.h"
#include "mailbox.h"
#include "render/student_task.h"

namespace ll::a4 {

#if LIGHTLAB_SOLUTION  // A4.4 (helpers)
namespace {

struct OctStackEntry {
  uint32_t node;
  float tNear;    // where the ray enters the node's cell
  Vec3 lo, hi;    // the node's cell (world space)
};

// Front to back. AnyHit: return at the first primitive hit. hit.t must start at ray.tmax.
template <bool AnyHit>
bool traverseOctree(const Octree& tree, const TraversalRay& r, Hit& hit, QueryCounters& counters) {
  float tRoot;
  if (!rayEntersBox(r, tree.bounds.min, tree.bounds.max, r.cullLimit(hit.t), tRoot)) return false;
  const OctreeNode* nodes = tree.nodes.data();
  OctStackEntry stack[kOctreeStackSize];
  int sp = 0;
  uint32_t current = 0;
  Vec3 lo = tree.bounds.min, hi = tree.bounds.max;
  uint64_t visited = 0, tested = 0;
  bool found = false;
  Mailbox mailbox;  // a primitive in several cells along the ray is tested once
  const Vec3& o = r.ray.origin;
  for (;;) {
    ++visited;
    const OctreeNode node = nodes[current];
    if (!node.isLeaf()) {
      // Per axis, the slab of the lower and of the upper half (near and far
      // plane distances; the near plane is the far one for negative directions).
      const Vec3 c = octreeCentre(lo, hi);
      float nearOf[3][2], farOf[3][2];
      for (int a = 0; a < 3; ++a) {
        const float tl = (lo[a] - o[a]) * r.invDir[a], tc = (c[a] - o[a]) * r.invDir[a],
                    th = (hi[a] - o[a]) * r.invDir[a];
        const bool neg = r.invDir[a] < 0.0f;
        nearOf[a][0] = neg ? tc : tl;
        farOf[a][0] = neg ? tl : tc;
        nearOf[a][1] = neg ? th : tc;
        farOf[a][1] = neg ? tc : th;
      }
      // The non-empty children the ray enters before the closest hit, sorted by entry.
      const float tLimit = r.cullLimit(hit.t);
      int order[8];
      float entry[8];
      int count = 0;
      for (int i = 0; i < 8; ++i) {
        const OctreeNode& child = nodes[node.offset + static_cast<uint32_t>(i)];
        if (child.count == 0) continue;  // an empty leaf: nothing to find there
        float tn = r.ray.tmin, tf = tLimit;
        for (int a = 0; a < 3; ++a) {
          const int half = (i >> a) & 1;
          tn = nearOf[a][half] > tn ? nearOf[a][half] : tn;  // a NaN operand keeps tn / tf (see rayEntersBox)
          tf = farOf[a][half] < tf ? farOf[a][half] : tf;
        }
        if (!(tn <= tf * kBvhRobustScale)) continue;
        int k = count++;
        for (; k > 0 && entry[k - 1] > tn; --k) {  // insertion sort, nearest first
          entry[k] = entry[k - 1];
          order[k] = order[k - 1];
        }
        entry[k] = tn;
        order[k] = i;
      }
      if (count > 0) {
        for (int k = count - 1; k >= 1; --k) {  // the farther ones wait on the stack, farthest deepest
          OctStackEntry& e = stack[sp++];
          e.node = node.offset + static_cast<uint32_t>(order[k]);
          e.tNear = entry[k];
          octreeChildCell(lo, hi, order[k], e.lo, e.hi);
        }
        Vec3 childLo, childHi;
        octreeChildCell(lo, hi, order[0], childLo, childHi);
        lo = childLo;
        hi = childHi;
        current = node.offset + static_cast<uint32_t>(order[0]);
        continue;
      }
    } else {
      found |= testLeafOnce<AnyHit>(tree, node.offset, node.offset + node.count, r, hit, mailbox, tested);
      if (AnyHit && found) break;
    }
    // Early exit: the pending cells start where this one ends or later, so
    // once the closest hit lies inside this cell all of them are dropped
    // here. A hit beyond this cell (its primitive reaches into later cells)
    // may still lose to a primitive of the next cell, which is then visited;
    // so are cells that share this cell's interval (the ray lies in a face).
    while (sp > 0 && found && !(stack[sp - 1].tNear <= r.cullLimit(hit.t))) --sp;
    if (sp == 0) break;
    --sp;
    current = stack[sp].node;
    lo = stack[sp].lo;
    hi = stack[sp].hi;
  }
  counters.nodesVisited += visited;
  counters.primitivesTested += tested;
  return found;
}

}  // namespace
#endif

bool intersectOctree(const Octree& tree, const Ray& ray, Hit& hit, QueryCounters& counters) {
  hit = Hit{};
  hit.t = ray.tmax;
#if LIGHTLAB_SOLUTION  // A4.4
  if (tree.nodes.empty()) return false;
  return traverseOctree<false>(tree, TraversalRay(ray, tree), hit, counters);
#else
  // Your A4.4 here (see its comment in a4_tasks.h), then delete the line below.
  (void)tree;
  (void)ray;
  (void)hit;
  (void)counters;
  LIGHTLAB_TODO_EXACT("A4.4", "octree traversal (assignments/a4_acceleration/octree_traversal.cpp)");
  return false;
#endif
}

bool occludedOctree(const Octree& tree, const Ray& ray, QueryCounters& counters) {
  Hit hit;  // for the leaf tests: anything closer than tmax
  hit.t = ray.tmax;
#if LIGHTLAB_SOLUTION  // A4.4
  if (tree.nodes.empty()) return false;
  return traverseOctree<true>(tree, TraversalRay(ray, tree), hit, counters);
#else
  // Your A4.4 here (see its comment in a4_tasks.h), then delete the line below.
  (void)tree;
  (void)ray;
  (void)hit;
  (void)counters;
  LIGHTLAB_TODO_EXACT("A4.4", "octree traversal (assignments/a4_acceleration/octree_traversal.cpp)");
  return false;
#endif
}

}  // namespace ll::a4
