// A3.1 Reflection direction.
#include "a3_tasks.h"
#include "render/student_task.h"

namespace ll::a3 {

Vec3 reflect(Vec3 d, Vec3 n) {
#if LIGHTLAB_SOLUTION  // A3.1
  return d - 2.0f * glm::dot(d, n) * n;
#else
  // Your A3.1 here (see its comment in a3_tasks.h), then delete the line below.
  (void)d;
  (void)n;
  LIGHTLAB_TODO("A3.1", "reflection direction (assignments/a3_whitted/reflect.cpp)");
  return Vec3(0.0f);
#endif
}

}  // namespace ll::a3
