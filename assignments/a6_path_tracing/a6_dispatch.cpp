// The task functions of A6 (a6_tasks.h) as the framework, the tests and your other
// tasks call them in the student tree: each call runs your function from the task's
// module (build/modules/lightlab_A6.N.so) or the task's reference, as the task's mode
// says (framework/tasks/task_modes.h). Framework code, compiled only when
// LIGHTLAB_SOLUTION is OFF; in the solution tree the task files are compiled in.
#include "a6_tasks.h"
#include "tasks/task_function.h"

namespace ll::a6 {

Vec3 sampleCosineHemisphere(Vec2 u) {
  static const tasks::TaskFunction<decltype(sampleCosineHemisphere)> f("A6.1", "sampleCosineHemisphere");
  return f(u);
}

float cosineHemispherePdf(float cosTheta) {
  static const tasks::TaskFunction<decltype(cosineHemispherePdf)> f("A6.1", "cosineHemispherePdf");
  return f(cosTheta);
}

Rgb nextEventEstimate(const ShadingPoint& x, const LightSample& light, const Bsdf& bsdf, const Tracer& tracer, bool mis) {
  static const tasks::TaskFunction<decltype(nextEventEstimate)> f("A6.2", "nextEventEstimate");
  return f(x, light, bsdf, tracer, mis);
}

bool russianRoulette(Rgb& throughput, float u) {
  static const tasks::TaskFunction<decltype(russianRoulette)> f("A6.3", "russianRoulette");
  return f(throughput, u);
}

float ggxDistribution(const Vec3& h, float alpha) {
  static const tasks::TaskFunction<decltype(ggxDistribution)> f("A6.4", "ggxDistribution");
  return f(h, alpha);
}

float smithMasking(const Vec3& w, float alpha) {
  static const tasks::TaskFunction<decltype(smithMasking)> f("A6.4", "smithMasking");
  return f(w, alpha);
}

Vec3 sampleGgxVisibleNormal(const Vec3& wo, float alpha, Vec2 u) {
  static const tasks::TaskFunction<decltype(sampleGgxVisibleNormal)> f("A6.4", "sampleGgxVisibleNormal");
  return f(wo, alpha, u);
}

}  // namespace ll::a6
