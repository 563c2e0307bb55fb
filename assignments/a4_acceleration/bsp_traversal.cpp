// A4.5 BSP tree traversal: closest hit (front to back across planes of any
// orientation, early exit once the closest hit lies in the current cell) and any hit.
#include "a4_tasks.h"
#include "mailbox.h"
#include "render/student_task.h"

namespace ll::a4 {

#if LIGHTLAB_SOLUTION  // A4.5 (helpers)
namespace {

struct BspStackEntry {
  uint32_t node;
  float tNear, tFar;  // the ray's parameter interval inside the node's cell
};

// Front to back. AnyHit: return at the first primitive hit. hit.t must start at ray.tmax.
template <bool AnyHit>
bool traverseBsp(const BspTree& tree, const TraversalRay& r, Hit& hit, QueryCounters& counters) {
  float tNear, tFar = r.ray.tmax;
  if (!rayEntersBox(r, tree.bounds.min, tree.bounds.max, r.cullLimit(r.ray.tmax), tNear)) return false;
  for (int a = 0; a < 3; ++a) {  // the root's exit, as a KD-tree traversal finds it
    const float face = r.invDir[a] < 0.0f ? tree.bounds.min[a] : tree.bounds.max[a];
    const float far = (face - r.ray.origin[a]) * r.invDir[a];
    tFar = far < tFar ? far : tFar;
  }
  const BspNode* nodes = tree.nodes.data();
  BspStackEntry stack[kBspStackSize];
  int sp = 0;
  uint32_t current = 0;
  uint64_t visited = 0, tested = 0;
  bool found = false;
  Mailbox mailbox;
  for (;;) {
    ++visited;
    const BspNode& node = nodes[current];
    if (!node.isLeaf()) {
      // The origin's signed distance to the plane and the direction's rate
      // across it: the ray crosses at tSplit = -distance / rate. Parallel
      // rays never cross (+-infinity) or lie in the plane (NaN). An
      // axis-aligned plane needs only its axis' components (as A4.3).
      const int axis = node.axis();
      float distance, rate, tSplit;
      if (axis != BspNode::kAnyPlane) {
        distance = r.ray.origin[axis] - node.offset;
        rate = r.ray.dir[axis];
        tSplit = (node.offset - r.ray.origin[axis]) * r.invDir[axis];
      } else {
        distance = glm::dot(node.normal, r.ray.origin) - node.offset;
        rate = glm::dot(node.normal, r.ray.dir);
        tSplit = -distance / rate;
      }
      const bool belowFirst = distance < 0.0f || (distance == 0.0f && rate <= 0.0f);
      const uint32_t first = belowFirst ? current + 1 : node.aboveChild();
      const uint32_t second = belowFirst ? node.aboveChild() : current + 1;
      if (tSplit <= 0.0f || tSplit > tFar + r.tSlack) {  // only the origin's side
        current = first;
      } else if (tSplit < tNear - r.tSlack) {  // already past the plane when entering the cell
        current = second;
      } else {  // both (also NaN: the ray lies in the plane, which belongs to both cells)
        stack[sp++] = {second, tSplit > tNear ? tSplit : tNear, tFar};
        tFar = tSplit < tFar ? tSplit : tFar;
        current = first;
      }
      continue;
    }
    found |= testLeafOnce<AnyHit>(tree, node.first(), node.first() + node.count(), r, hit, mailbox, tested);
    if (AnyHit && found) break;
    // Early exit, as in a KD-tree: the pending cells start at or after this one's end.
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

bool intersectBsp(const BspTree& tree, const Ray& ray, Hit& hit, QueryCounters& counters) {
  hit = Hit{};
  hit.t = ray.tmax;
#if LIGHTLAB_SOLUTION  // A4.5
  if (tree.nodes.empty()) return false;
  return traverseBsp<false>(tree, TraversalRay(ray, tree), hit, counters);
#else
  // Your A4.5 here (see its comment in a4_tasks.h), then delete the line below.
  (void)tree;
  (void)ray;
  (void)hit;
  (void)counters;
  LIGHTLAB_TODO_EXACT("A4.5", "BSP tree traversal (assignments/a4_acceleration/bsp_traversal.cpp)");
  return false;
#endif
}

bool occludedBsp(const BspTree& tree, const Ray& ray, QueryCounters& counters) {
  Hit hit;  // for the leaf tests: anything closer than tmax
  hit.t = ray.tmax;
#if LIGHTLAB_SOLUTION  // A4.5
  if (tree.nodes.empty()) return false;
  return traverseBsp<true>(tree, TraversalRay(ray, tree), hit, counters);
#else
  // Your A4.5 here (see its comment in a4_tasks.h), then delete the line below.
  (void)tree;
  (void)ray;
  (void)hit;
  (void)counters;
  LIGHTLAB_TODO_EXACT("A4.5", "BSP tree traversal (assignments/a4_acceleration/bsp_traversal.cpp)");
  return false;
#endif
}

}  // namespace ll::a4
