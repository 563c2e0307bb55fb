// A4.3 KD-tree traversal: closest hit (front to back, early exit once the
// closest hit lies in the current cell) and any hit.
#include "a4_tasks.h"
#include "mailbox.h"
#include "render/student_task.h"

namespace ll::a4 {

#if LIGHTLAB_SOLUTION  // A4.3 (helpers)
namespace {

struct KdStackEntry {
  uint32_t node;
  float tNear, tFar;  // the ray's parameter interval inside the node's cell
};

// Front to back. AnyHit: return at the first primitive hit. hit.t must start at ray.tmax.
template <bool AnyHit>
bool traverseKd(const KdTree& tree, const TraversalRay& r, Hit& hit, QueryCounters& counters) {
  float tNear, tFar = r.ray.tmax;
  if (!rayEntersBox(r, tree.bounds.min, tree.bounds.max, r.cullLimit(r.ray.tmax), tNear)) return false;
  // The root's exit (rayEntersBox reports only the entry); the far face is lo
  // for a negative direction (-0 included: invDir = -infinity).
  for (int a = 0; a < 3; ++a) {
    const float face = r.invDir[a] < 0.0f ? tree.bounds.min[a] : tree.bounds.max[a];
    const float far = (face - r.ray.origin[a]) * r.invDir[a];
    tFar = far < tFar ? far : tFar;  // NaN (origin on the face, axis-parallel) keeps tFar
  }
  const KdNode* nodes = tree.nodes.data();
  KdStackEntry stack[kKdStackSize];
  int sp = 0;
  uint32_t current = 0;
  uint64_t visited = 0, tested = 0;
  bool found = false;
  Mailbox mailbox;  // a primitive in several cells along the ray is tested once
  const auto origin = components(r.ray.origin), dir = components(r.ray.dir), invDir = components(r.invDir);
  for (;;) {
    ++visited;
    const KdNode node = nodes[current];
    if (!node.isLeaf()) {
      const int a = node.axis();
      const float split = node.split(), o = origin[a], d = dir[a];
      // The ray crosses the plane at tSplit: before it, it is in `first` (the
      // origin's side; from an origin on the plane, the side it goes into, as
      // tSplit = 0), after it in `second`. Axis-parallel: +-infinity (never
      // crosses), or NaN when it lies in the plane. A child without
      // primitives is never entered (its flag saves loading it).
      const float tSplit = (split - o) * invDir[a];
      const bool belowFirst = o < split || (o == split && d <= 0.0f);
      const uint32_t first = belowFirst ? current + 1 : node.aboveChild();
      const uint32_t second = belowFirst ? node.aboveChild() : current + 1;
      const bool firstEmpty = belowFirst ? node.belowEmpty() : node.aboveEmpty();
      const bool secondEmpty = belowFirst ? node.aboveEmpty() : node.belowEmpty();
      if (tSplit <= 0.0f || tSplit > tFar + r.tSlack) {  // only the origin's side (the sign is exact)
        if (!firstEmpty) {
          current = first;
          continue;
        }
      } else if (tSplit < tNear - r.tSlack) {  // already past the plane when entering the cell
        if (!secondEmpty) {
          current = second;
          continue;
        }
      } else {  // both (also NaN: the ray lies in the plane, which belongs to both cells)
        const float secondNear = tSplit > tNear ? tSplit : tNear;
        if (!firstEmpty) {
          if (!secondEmpty) stack[sp++] = {second, secondNear, tFar};
          tFar = tSplit < tFar ? tSplit : tFar;
          current = first;
          continue;
        }
        if (!secondEmpty) {
          tNear = secondNear;
          current = second;
          continue;
        }
      }
      // Every cell the ray enters here is empty: on to the pending ones.
    } else {
      found |= testLeafOnce<AnyHit>(tree, node.first(), node.first() + node.count(), r, hit, mailbox, tested);
      if (AnyHit && found) break;
    }
    // Early exit: the pending cells start where this one ends (tFar) or
    // later, so once the closest hit lies inside this cell (hit.t + slack <
    // tFar) all of them are dropped here. A hit beyond this cell's end (the
    // primitive reaches into later cells) may still lose to a primitive of
    // the next cell, which is then visited. A cell lying in the same plane as
    // the ray shares this cell's interval and is visited too.
    while (sp > 0 && found && !(stack[sp - 1].tNear <= r.cullLimit(hit.t))) --sp;
    if (sp == 0) break;
    --sp;
    current = stack[sp].node;
    tNear = stack[sp].tNear;
    tFar = stack[sp].tFar;
  }
  counters.nodesVisited += visited;
  counters.primitivesTested += tested;
  return found;
}

}  // namespace
#endif

bool intersectKdTree(const KdTree& tree, const Ray& ray, Hit& hit, QueryCounters& counters) {
  hit = Hit{};
  hit.t = ray.tmax;
#if LIGHTLAB_SOLUTION  // A4.3
  if (tree.nodes.empty()) return false;
  return traverseKd<false>(tree, TraversalRay(ray, tree), hit, counters);
#else
  // Your A4.3 here (see its comment in a4_tasks.h), then delete the line below.
  (void)tree;
  (void)ray;
  (void)hit;
  (void)counters;
  LIGHTLAB_TODO_EXACT("A4.3", "KD-tree traversal (assignments/a4_acceleration/kdtree_traversal.cpp)");
  return false;
#endif
}

bool occludedKdTree(const KdTree& tree, const Ray& ray, QueryCounters& counters) {
  Hit hit;  // for the leaf tests: anything closer than tmax
  hit.t = ray.tmax;
#if LIGHTLAB_SOLUTION  // A4.3
  if (tree.nodes.empty()) return false;
  return traverseKd<true>(tree, TraversalRay(ray, tree), hit, counters);
#else
  // Your A4.3 here (see its comment in a4_tasks.h), then delete the line below.
  (void)tree;
  (void)ray;
  (void)hit;
  (void)counters;
  LIGHTLAB_TODO_EXACT("A4.3", "KD-tree traversal (assignments/a4_acceleration/kdtree_traversal.cpp)");
  return false;
#endif
}

}  // namespace ll::a4
