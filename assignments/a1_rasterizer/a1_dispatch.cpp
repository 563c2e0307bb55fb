// The task functions of A1 (a1_tasks.h) as the framework, the tests and your other
// tasks call them in the student tree: each call runs your function from the task's
// module (build/modules/lightlab_A1.N.so) or the task's reference, as the task's mode
// says (framework/tasks/task_modes.h). Framework code, compiled only when
// LIGHTLAB_SOLUTION is OFF; in the solution tree the task files are compiled in.
#include "a1_tasks.h"
#include "tasks/task_function.h"

namespace ll::a1 {

Mat4 viewProjection(const Camera& camera, float near, float far) {
  static const tasks::TaskFunction<decltype(viewProjection)> f("A1.1", "viewProjection");
  return f(camera, near, far);
}

double edgeFunction(Vec2 a, Vec2 b, Vec2 p) {
  static const tasks::TaskFunction<decltype(edgeFunction)> f("A1.2", "edgeFunction");
  return f(a, b, p);
}

bool isTopLeft(Vec2 a, Vec2 b) {
  static const tasks::TaskFunction<decltype(isTopLeft)> f("A1.2", "isTopLeft");
  return f(a, b);
}

bool depthTest(float z, float& stored) {
  static const tasks::TaskFunction<decltype(depthTest)> f("A1.3", "depthTest");
  return f(z, stored);
}

LightTerms blinnPhong(Vec3 n, Vec3 v, Vec3 l, Rgb irradiance, float shininess) {
  static const tasks::TaskFunction<decltype(blinnPhong)> f("A1.4", "blinnPhong");
  return f(n, v, l, irradiance, shininess);
}

Rgb sampleTexture(const MipChain& mips, Vec2 uv, float lod, TextureFilter filter) {
  static const tasks::TaskFunction<decltype(sampleTexture)> f("A1.5", "sampleTexture");
  return f(mips, uv, lod, filter);
}

}  // namespace ll::a1
