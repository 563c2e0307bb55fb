// Edit, save, see (lightlab gui --watch; on by default in the student tree).
// When the student saves a task's file, the GUI rebuilds that task's module
// with the project's own build (tasks/module_builder.h), in the background.
// A good build: between two renders every pane stops, the new module is
// loaded (tasks::reloadStudentModules), and every pane renders again with
// its scene, camera, technique and parameters. A failed build: the compiler's
// first error is shown in the side panel (the whole log one click away) and
// the panes keep the last good module's images.
#pragma once

#include <chrono>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "tasks/module_builder.h"

namespace ll::gui {

struct AppState;

struct HotReloadState {
  enum class Phase {
    Off,       // not the student tree, or --watch off
    Watching,  // the last build (if any) is loaded
    Building,  // cmake --build runs
    Stopping,  // built; waiting for every pane to stop before loading it
    Failed,    // the last build failed: the previous module stays loaded
  };
  Phase phase = Phase::Off;
  std::unique_ptr<tasks::TaskFileWatcher> watcher;
  std::string sourceRoot, buildDir;
  std::chrono::steady_clock::time_point lastPoll;
  std::vector<int> queued;  // saved while a build ran: built next
  std::future<tasks::ModuleBuild> build;
  tasks::ModuleBuild last;  // the last finished build
  std::chrono::steady_clock::time_point savedAt;  // when the save that started this build was seen
  int reloads = 0;          // modules loaded since start
  bool showLog = false;     // the full build log window
  // Save-to-image latency of the last reload: from the save being seen to every
  // active pane's first finished pass with the new code (seconds; < 0 = pending).
  double buildSeconds = 0.0, latencySeconds = -1.0;
  std::vector<uint64_t> awaitedRequests;  // per pane: the first request rendered with the new module
  bool measuring = false;
  std::chrono::steady_clock::time_point stoppingSince;  // Stopping: since when
  bool stuckReported = false;  // a pane that does not stop (student code in an endless loop) was reported
};

// Starts watching when this build loads student modules and `enabled`.
void startHotReload(AppState& app, bool enabled);
// Once per frame: poll the files (4 times a second), start and collect builds,
// stop the panes and load a good build between renders.
void updateHotReload(AppState& app);
// The side panel's "Your code" status: watching, building, the first compiler
// error, the reload time; and the build log window when asked for.
void drawHotReloadStatus(AppState& app);

const char* hotReloadPhaseName(HotReloadState::Phase phase);

}  // namespace ll::gui
