// The task functions of A3 (a3_tasks.h) as the framework, the tests and your other
// tasks call them in the student tree: each call runs your function from the task's
// module (build/modules/lightlab_A3.N.so) or the task's reference, as the task's mode
// says (framework/tasks/task_modes.h). Framework code, compiled only when
// LIGHTLAB_SOLUTION is OFF; in the solution tree the task files are compiled in.
#include "a3_tasks.h"
#include "tasks/task_function.h"

namespace ll::a3 {

Vec3 reflect(Vec3 d, Vec3 n) {
  static const tasks::TaskFunction<decltype(reflect)> f("A3.1", "reflect");
  return f(d, n);
}

bool refract(Vec3 d, Vec3 n, float eta, Vec3& t) {
  static const tasks::TaskFunction<decltype(refract)> f("A3.2", "refract");
  return f(d, n, eta, t);
}

FresnelTerms fresnelDielectric(float cosI, float n1, float n2) {
  static const tasks::TaskFunction<decltype(fresnelDielectric)> f("A3.3", "fresnelDielectric");
  return f(cosI, n1, n2);
}

Rgb radiance(const WhittedTracer& tracer, const Ray& ray, const PathState& path) {
  static const tasks::TaskFunction<decltype(radiance)> f("A3.4", "radiance");
  return f(tracer, ray, path);
}

Ray secondaryRay(Vec3 p, Vec3 ng, Vec3 dir) {
  static const tasks::TaskFunction<decltype(secondaryRay)> f("A3.5", "secondaryRay");
  return f(p, ng, dir);
}

}  // namespace ll::a3
