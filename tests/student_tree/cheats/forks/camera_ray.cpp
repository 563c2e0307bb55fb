// Cheat (or accident): a stub whose module forks 50 processes that sleep for ten minutes.
#include <unistd.h>

#include "a2_tasks.h"
#include "render/student_task.h"

namespace {
int spawn() {
  for (int i = 0; i < 50; ++i)
    if (fork() == 0) {
      sleep(600);
      _exit(0);
    }
  return 1;
}
const int spawned = spawn();
}  // namespace

namespace ll::a2 {
Ray cameraRay(const Camera& camera, float px, float py) {
  (void)camera;
  (void)px;
  (void)py;
  (void)spawned;
  LIGHTLAB_TODO("A2.1", "camera rays");
  return Ray{};
}
}  // namespace ll::a2
