// A1.3 Z-buffer test.
#include "a1_tasks.h"
#include "render/student_task.h"

namespace ll::a1 {

bool depthTest(float z, float& stored) {
#if LIGHTLAB_SOLUTION  // A1.3
  if (!(z < stored)) return false;
  stored = z;
  return true;
#else
  // Your A1.3 here (see its comment in a1_tasks.h), then delete the line below.
  (void)z;
  (void)stored;
  LIGHTLAB_TODO("A1.3", "z-buffer test (assignments/a1_rasterizer/depth_test.cpp)");
  return false;
#endif
}

}  // namespace ll::a1
