#include "gui/hot_reload.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "gui/app_actions.h"
#include "gui/app_state.h"
#include "gui/side_panel.h"
#include "tasks/task_catalog.h"
#include "tasks/task_modes.h"
#include "tasks/task_modules.h"

namespace ll::gui {

namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kPollEvery = std::chrono::milliseconds(100);

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string taskIds(const std::vector<int>& tasks) {
  std::string out;
  for (int t : tasks) out += (out.empty() ? "" : " ") + std::string(tasks::taskCatalog()[static_cast<size_t>(t)].id);
  return out;
}

// One line on stdout (the benchmark and the tests read it) and in the messages.
void say(AppState& app, const std::string& text, bool error) {
  addMessage(app, text, error);
  std::printf("lightlab: %s\n", text.c_str());
  std::fflush(stdout);
}

void startBuild(AppState& app) {
  HotReloadState& h = app.hotReload;
  std::vector<int> tasks;
  tasks.swap(h.queued);
  h.phase = HotReloadState::Phase::Building;
  h.build = std::async(std::launch::async, [tasks, dir = h.buildDir, root = h.sourceRoot] {
    return tasks::buildTaskModules(tasks, dir, root);
  });
}

void queueChanges(HotReloadState& h) {
  if (Clock::now() - h.lastPoll < kPollEvery) return;
  h.lastPoll = Clock::now();
  for (int t : h.watcher->changed())
    if (std::find(h.queued.begin(), h.queued.end(), t) == h.queued.end()) h.queued.push_back(t);
}

// Every active pane has finished a full pass of a render begun after the reload.
bool newImagesShown(const AppState& app) {
  const HotReloadState& h = app.hotReload;
  for (int i = 0; i < kMaxPanes; ++i) {
    if (!paneActive(app, i)) continue;
    const PaneSnapshot& s = app.panes[static_cast<size_t>(i)].shown;
    if (s.phase == PaneSnapshot::Phase::Failed && s.starts > h.awaitedRequests[static_cast<size_t>(i)]) continue;
    if (s.starts <= h.awaitedRequests[static_cast<size_t>(i)] || s.passes < 1 || s.preview || s.imageRequest != s.request)
      return false;
  }
  return true;
}

}  // namespace

const char* hotReloadPhaseName(HotReloadState::Phase phase) {
  switch (phase) {
    case HotReloadState::Phase::Off: return "off";
    case HotReloadState::Phase::Watching: return "watching";
    case HotReloadState::Phase::Building: return "building";
    case HotReloadState::Phase::Stopping: return "loading";
    case HotReloadState::Phase::Failed: return "failed";
  }
  return "off";
}

void startHotReload(AppState& app, bool enabled) {
  HotReloadState& h = app.hotReload;
  h.sourceRoot = tasks::sourceRoot();
  h.buildDir = tasks::buildRoot();
  if (!enabled || !tasks::modulesEnabled() || h.buildDir.empty()) return;
  h.watcher = std::make_unique<tasks::TaskFileWatcher>(h.sourceRoot);
  h.phase = HotReloadState::Phase::Watching;
}

void updateHotReload(AppState& app) {
  HotReloadState& h = app.hotReload;
  if (h.phase == HotReloadState::Phase::Off) return;
  queueChanges(h);
  switch (h.phase) {
    case HotReloadState::Phase::Watching:
    case HotReloadState::Phase::Failed:
      if (!h.queued.empty()) {
        h.savedAt = Clock::now();
        h.latencySeconds = -1.0;
        h.measuring = false;
        say(app, "saved " + taskIds(h.queued) + ": building", false);
        startBuild(app);
      }
      break;
    case HotReloadState::Phase::Building:
      if (h.build.wait_for(std::chrono::seconds(0)) != std::future_status::ready) break;
      h.last = h.build.get();
      h.buildSeconds = h.last.seconds;
      if (!h.last.ok) {
        h.phase = HotReloadState::Phase::Failed;
        say(app, "build of " + taskIds(h.last.tasks) + " failed: " + h.last.firstError.oneLine() +
                     " (the panes keep the last good code)", true);
        break;
      }
      // Between two renders: stop every pane, and load the new module once none runs student code.
      for (PaneState& p : app.panes) p.renderer->stop();
      h.phase = HotReloadState::Phase::Stopping;
      h.stoppingSince = Clock::now();
      h.stuckReported = false;
      [[fallthrough]];
    case HotReloadState::Phase::Stopping: {
      for (int i = 0; i < kMaxPanes; ++i)
        if (!app.panes[static_cast<size_t>(i)].renderer->finished()) {
          if (!h.stuckReported && secondsSince(h.stoppingSince) > 3.0) {
            h.stuckReported = true;
            say(app, std::string("pane ") + static_cast<char>('A' + i) +
                         " does not stop: it is still in your code (an endless loop?). The new code loads when it returns.",
                true);
          }
          return;
        }
      tasks::reloadStudentModules();
      ++h.reloads;
      h.awaitedRequests.assign(kMaxPanes, 0);
      for (int i = 0; i < kMaxPanes; ++i) {
        PaneState& p = app.panes[static_cast<size_t>(i)];
        h.awaitedRequests[static_cast<size_t>(i)] = p.renderer->snapshot().starts;
        p.dirty = true;  // same scene, camera, technique and parameters; the new code
      }
      h.measuring = true;
      h.phase = HotReloadState::Phase::Watching;
      char buf[160];
      std::snprintf(buf, sizeof buf, "%s rebuilt in %.1f s and reloaded", taskIds(h.last.tasks).c_str(), h.buildSeconds);
      say(app, buf, false);
      if (!h.queued.empty()) startBuild(app);  // saved again meanwhile
      break;
    }
    case HotReloadState::Phase::Off:
      break;
  }
  if (h.measuring && h.phase == HotReloadState::Phase::Watching && newImagesShown(app)) {
    h.measuring = false;
    h.latencySeconds = secondsSince(h.savedAt);
    char buf[160];
    std::snprintf(buf, sizeof buf, "new image %.1f s after the save (build %.1f s)", h.latencySeconds, h.buildSeconds);
    say(app, buf, false);
  }
}

void drawHotReloadStatus(AppState& app) {
  HotReloadState& h = app.hotReload;
  if (h.phase == HotReloadState::Phase::Off) return;
  switch (h.phase) {
    case HotReloadState::Phase::Building:
      ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "Building %s ... %.0f s", taskIds(h.queued.empty() ? h.last.tasks : h.queued).c_str(),
                         secondsSince(h.savedAt));
      break;
    case HotReloadState::Phase::Stopping:
      ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "Loading your new code ...");
      break;
    case HotReloadState::Phase::Failed:
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.45f, 0.45f, 1));
      ImGui::TextWrapped("Build failed -- the panes show your last good code:\n%s", h.last.firstError.oneLine().c_str());
      ImGui::PopStyleColor();
      recordWidget(app, "reload.error");
      if (ImGui::SmallButton("Show the build log")) h.showLog = true;
      recordWidget(app, "reload.log_button");
      break;
    default:
      if (h.reloads == 0)
        ImGui::TextWrapped("Save a task's file: it rebuilds and the panes show it.");
      else if (h.latencySeconds >= 0)
        ImGui::TextWrapped("Reloaded %s: built in %.1f s, new image %.1f s after the save.", taskIds(h.last.tasks).c_str(),
                           h.buildSeconds, h.latencySeconds);
      else
        ImGui::TextWrapped("Reloaded %s (built in %.1f s); rendering ...", taskIds(h.last.tasks).c_str(), h.buildSeconds);
      recordWidget(app, "reload.status");
      break;
  }
  if (!h.showLog) return;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowSize(ImVec2(vp->Size.x * 0.6f, vp->Size.y * 0.6f), ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(vp->Size.x * 0.5f, vp->Size.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::Begin("Build log", &h.showLog)) {
    ImGui::TextWrapped("cmake --build %s --target %s", h.buildDir.c_str(),
                       h.last.tasks.empty() ? "" : tasks::moduleTarget(h.last.tasks.front()).c_str());
    ImGui::Separator();
    ImGui::BeginChild("log", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
    ImGui::TextUnformatted(h.last.log.c_str());
    ImGui::EndChild();
  }
  ImGui::End();
}

}  // namespace ll::gui
