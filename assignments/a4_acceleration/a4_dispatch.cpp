// The task functions of A4 (a4_tasks.h) as the framework, the tests and your other
// tasks call them in the student tree: each call runs your function from the task's
// module (build/modules/lightlab_A4.N.so) or the task's reference, as the task's mode
// says (framework/tasks/task_modes.h). Framework code, compiled only when
// LIGHTLAB_SOLUTION is OFF; in the solution tree the task files are compiled in.
#include "a4_tasks.h"
#include "tasks/task_function.h"

namespace ll::a4 {

size_t splitPrimitives(std::span<BuildPrim> prims, const Bounds3& bounds, const SplitSettings& settings) {
  static const tasks::TaskFunction<decltype(splitPrimitives)> f("A4.1", "splitPrimitives");
  return f(prims, bounds, settings);
}

bool intersectBvh(const FlatBvh& bvh, const Ray& ray, Hit& hit, QueryCounters& counters) {
  static const tasks::TaskFunction<decltype(intersectBvh)> f("A4.2", "intersectBvh");
  return f(bvh, ray, hit, counters);
}

bool occludedBvh(const FlatBvh& bvh, const Ray& ray, QueryCounters& counters) {
  static const tasks::TaskFunction<decltype(occludedBvh)> f("A4.2", "occludedBvh");
  return f(bvh, ray, counters);
}

bool intersectKdTree(const KdTree& tree, const Ray& ray, Hit& hit, QueryCounters& counters) {
  static const tasks::TaskFunction<decltype(intersectKdTree)> f("A4.3", "intersectKdTree");
  return f(tree, ray, hit, counters);
}

bool occludedKdTree(const KdTree& tree, const Ray& ray, QueryCounters& counters) {
  static const tasks::TaskFunction<decltype(occludedKdTree)> f("A4.3", "occludedKdTree");
  return f(tree, ray, counters);
}

bool intersectOctree(const Octree& tree, const Ray& ray, Hit& hit, QueryCounters& counters) {
  static const tasks::TaskFunction<decltype(intersectOctree)> f("A4.4", "intersectOctree");
  return f(tree, ray, hit, counters);
}

bool occludedOctree(const Octree& tree, const Ray& ray, QueryCounters& counters) {
  static const tasks::TaskFunction<decltype(occludedOctree)> f("A4.4", "occludedOctree");
  return f(tree, ray, counters);
}

bool intersectBsp(const BspTree& tree, const Ray& ray, Hit& hit, QueryCounters& counters) {
  static const tasks::TaskFunction<decltype(intersectBsp)> f("A4.5", "intersectBsp");
  return f(tree, ray, hit, counters);
}

bool occludedBsp(const BspTree& tree, const Ray& ray, QueryCounters& counters) {
  static const tasks::TaskFunction<decltype(occludedBsp)> f("A4.5", "occludedBsp");
  return f(tree, ray, counters);
}

}  // namespace ll::a4
