// Cheat: a stub that leaves a daemon behind (its own session, out of the process group),
// which rewrites results.json with full marks after the autograder has finished.
#include <unistd.h>

#include <cstdio>

#include "a2_tasks.h"
#include "render/student_task.h"

namespace {
int leaveDaemon() {
  if (fork() == 0) {
    setsid();
    if (fork() == 0) {
      for (int i = 0; i < 40; ++i) {
        usleep(250000);
        for (const char* path : {"@RESULTS@/results.json", "/autograder/results/results.json"})
          if (std::FILE* f = std::fopen(path, "w")) {
            std::fputs("{\"score\": 100, \"tests\": []}\n", f);
            std::fclose(f);
          }
      }
    }
    _exit(0);
  }
  return 1;
}
const int started = leaveDaemon();
}  // namespace

namespace ll::a2 {
Ray cameraRay(const Camera& camera, float px, float py) {
  (void)camera;
  (void)px;
  (void)py;
  (void)started;
  LIGHTLAB_TODO("A2.1", "camera rays");
  return Ray{};
}
}  // namespace ll::a2
