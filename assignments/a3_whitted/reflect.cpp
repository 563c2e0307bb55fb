// A3.1 Reflection direction.
#include "a3_tasks.h"
#include "render/student_task.h"

namespace ll::a3 {

Vec3 reflect(Vec3 d, Vec3 n) {
#if LIGHTLAB_SOLUTION  // A3.1
  return d - 2.0f * glm::dot(d, n) * n;
#else
  (void)n;
  LIGHTLAB_TODO("A3.1", "reflection direction (assignments/a3_whitted/reflect.cpp)");
  return d;  // stand-in: the ray goes straight on, so mirrors look like holes
#endif
}

}  // namespace ll::a3
