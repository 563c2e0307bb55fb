// A1.3 Z-buffer test.
#include "a1_tasks.h"
#include "rasterizer.h"
#include "render/student_task.h"

namespace ll::a1 {

bool depthTest(float z, float& stored) {
#if LIGHTLAB_SOLUTION  // A1.3
  if (!(z < stored)) return false;
  stored = z;
  return true;
#else
  LIGHTLAB_TODO("A1.3", "z-buffer test (assignments/a1_rasterizer/depth_test.cpp)");
  return referenceDepthTest(z, stored);  // framework fallback
#endif
}

}  // namespace ll::a1
