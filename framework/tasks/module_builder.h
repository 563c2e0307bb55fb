// Hot reload, the build half (lightlab gui --watch, the student tree): notice
// that the student saved a task's file, and rebuild that task's module with the
// project's own build (`cmake --build BUILD --target lightlab_task_A2_4`, so
// the flags, ccache and the link-time module check are the build's). Loading
// the new module is task_modules.h's reloadStudentModules. No GUI here: the
// GUI (gui/hot_reload.h) polls these from its main loop.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tasks/visibility.h"

namespace ll::tasks {

// The source tree and the build folder this program was built from.
LIGHTLAB_FRAMEWORK_ONLY std::string sourceRoot();
LIGHTLAB_FRAMEWORK_ONLY std::string buildRoot();

// Polls the modification times of every task's file (assignments/<folder>/<file>).
class TaskFileWatcher {
 public:
  explicit TaskFileWatcher(const std::string& sourceRoot);
  // Tasks whose file changed since the last call (or since construction), in catalog order.
  std::vector<int> changed();

 private:
  struct Watched {
    int task;
    std::filesystem::path path;
    std::filesystem::file_time_type time;
  };
  std::vector<Watched> files_;
};

// One line of compiler output: "assignments/a2_raycasting/blinn_phong.cpp:14:3: error: ...".
struct CompilerMessage {
  std::string file;  // as the compiler printed it, made relative to the source root if inside it
  int line = 0, column = 0;  // 0 = not given (a linker or module-check error)
  std::string text;          // the message after "error: "
  bool empty() const { return text.empty(); }
  std::string oneLine() const;  // file:line:column: text
};

// The first error of a build log: a compiler's "file:line:col: error: ...",
// else the first line that says "error" (the linker's, the module check's).
// Paths under `sourceRoot` are shown relative to it.
LIGHTLAB_FRAMEWORK_ONLY CompilerMessage firstCompilerError(const std::string& log, const std::string& sourceRoot);

struct ModuleBuild {
  std::vector<int> tasks;  // what was rebuilt
  bool ok = false;
  double seconds = 0.0;  // wall time of the build
  std::string log;       // the build's output (stdout and stderr, capped)
  CompilerMessage firstError;  // when !ok
};

// The build target of a task's module (lightlab_task_A2_4).
LIGHTLAB_FRAMEWORK_ONLY std::string moduleTarget(int task);

// Builds the modules of `tasks` in `buildDir` (blocking; run it off the UI thread).
LIGHTLAB_FRAMEWORK_ONLY ModuleBuild buildTaskModules(const std::vector<int>& tasks, const std::string& buildDir,
                                                     const std::string& sourceRoot);

}  // namespace ll::tasks
