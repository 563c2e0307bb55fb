// Cheat: a stub (A2.4 unwritten) whose module starts a daemon that rewrites the files the
// renders leave in their working folder: render statistics without "missing_tasks".
#include <dirent.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "a2_tasks.h"
#include "render/student_task.h"

namespace {
int tamper() {
  if (fork() == 0) {
    setsid();
    for (int i = 0; i < 200; ++i) {
      usleep(50000);
      if (DIR* d = opendir(".")) {
        while (dirent* e = readdir(d)) {
          const std::string name = e->d_name;
          if (name.size() > 11 && name.substr(name.size() - 11) == ".stats.json")
            if (std::FILE* f = std::fopen(name.c_str(), "w")) {
              std::fputs("{\"missing_tasks\": {}, \"task_violations\": {}}\n", f);
              std::fclose(f);
            }
        }
        closedir(d);
      }
    }
    _exit(0);
  }
  return 1;
}
const int started = tamper();
}  // namespace

namespace ll::a2 {
Rgb blinnPhong(const ShadingInput& s, const LightInput& light) {
  (void)s;
  (void)light;
  (void)started;
  LIGHTLAB_TODO("A2.4", "Blinn-Phong shading");
  return Rgb(0.0f);
}
}  // namespace ll::a2
