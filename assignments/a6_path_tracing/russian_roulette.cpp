// A6.3 Russian roulette.
#include <algorithm>

#include "a6_tasks.h"
#include "render/student_task.h"

namespace ll::a6 {

bool russianRoulette(Rgb& throughput, float u) {
#if LIGHTLAB_SOLUTION  // A6.3
  const float q = std::clamp(maxComponent(throughput), 0.05f, 0.95f);
  if (u >= q) return false;
  throughput /= q;  // the survivors carry the weight of the paths that ended: unbiased
  return true;
#else
  // Your A6.3 here (see its comment in a6_tasks.h), then delete the line below.
  (void)throughput;
  (void)u;
  LIGHTLAB_TODO("A6.3", "Russian roulette (assignments/a6_path_tracing/russian_roulette.cpp)");
  return false;
#endif
}

}  // namespace ll::a6
