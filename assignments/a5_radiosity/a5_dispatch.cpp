// The task functions of A5 (a5_tasks.h) as the framework, the tests and your other
// tasks call them in the student tree: each call runs your function from the task's
// module (build/modules/lightlab_A5.N.so) or the task's reference, as the task's mode
// says (framework/tasks/task_modes.h). Framework code, compiled only when
// LIGHTLAB_SOLUTION is OFF; in the solution tree the task files are compiled in.
#include "a5_tasks.h"
#include "tasks/task_function.h"

namespace ll::a5 {

float pointToPolygonFormFactor(Vec3 x, Vec3 n, const Vec3* vertices, int count) {
  static const tasks::TaskFunction<decltype(pointToPolygonFormFactor)> f("A5.1", "pointToPolygonFormFactor");
  return f(x, n, vertices, count);
}

float gaussSeidelSweep(const RadiositySystem& system, std::vector<Rgb>& b) {
  static const tasks::TaskFunction<decltype(gaussSeidelSweep)> f("A5.2", "gaussSeidelSweep");
  return f(system, b);
}

int shootLargest(const RadiositySystem& system, std::vector<Rgb>& b, std::vector<Rgb>& unshot) {
  static const tasks::TaskFunction<decltype(shootLargest)> f("A5.3", "shootLargest");
  return f(system, b, unshot);
}

}  // namespace ll::a5
