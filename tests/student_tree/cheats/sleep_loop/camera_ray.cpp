// Accident: an endless loop that sleeps (no CPU time spent, so only wall-clock limits catch it).
#include <unistd.h>

#include "a2_tasks.h"

namespace ll::a2 {
Ray cameraRay(const Camera& camera, float px, float py) {
  (void)camera;
  (void)px;
  (void)py;
  for (;;) sleep(1);
}
}  // namespace ll::a2
