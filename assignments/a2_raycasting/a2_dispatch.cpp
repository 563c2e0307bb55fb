// The task functions of A2 (a2_tasks.h) as the framework, the tests and your other
// tasks call them in the student tree: each call runs your function from the task's
// module (build/modules/lightlab_A2.N.so) or the task's reference, as the task's mode
// says (framework/tasks/task_modes.h). Framework code, compiled only when
// LIGHTLAB_SOLUTION is OFF; in the solution tree the task files are compiled in.
#include "a2_tasks.h"
#include "tasks/task_function.h"

namespace ll::a2 {

Ray cameraRay(const Camera& camera, float px, float py) {
  static const tasks::TaskFunction<decltype(cameraRay)> f("A2.1", "cameraRay");
  return f(camera, px, py);
}

bool raySphere(const Ray& ray, const Sphere& sphere, float& t) {
  static const tasks::TaskFunction<decltype(raySphere)> f("A2.2", "raySphere");
  return f(ray, sphere, t);
}

bool rayTriangle(const Ray& ray, const Vec3& p0, const Vec3& p1, const Vec3& p2, float& t, float& b1, float& b2) {
  static const tasks::TaskFunction<decltype(rayTriangle)> f("A2.3", "rayTriangle");
  return f(ray, p0, p1, p2, t, b1, b2);
}

Rgb blinnPhong(const ShadingInput& surface, const LightInput& light) {
  static const tasks::TaskFunction<decltype(blinnPhong)> f("A2.4", "blinnPhong");
  return f(surface, light);
}

Ray shadowRay(const SurfacePoint& sp, const Vec3& toLight, float distance) {
  static const tasks::TaskFunction<decltype(shadowRay)> f("A2.5", "shadowRay");
  return f(sp, toLight, distance);
}

}  // namespace ll::a2
