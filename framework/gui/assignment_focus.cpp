#include "gui/assignment_focus.h"

#include <algorithm>
#include <filesystem>

#include "core/error.h"
#include "gui/app_actions.h"
#include "tasks/task_catalog.h"
#include "tasks/task_modes.h"

namespace ll::gui {

namespace fs = std::filesystem;

std::vector<std::string> assignmentNames() {
  std::vector<std::string> names;
  for (const tasks::TaskInfo& t : tasks::taskCatalog())
    if (std::find(names.begin(), names.end(), t.assignment()) == names.end()) names.push_back(t.assignment());
  return names;
}

std::string assignmentPresetPath(const std::string& assignment) {
  std::vector<std::string> folders{"data/presets/assignments"};
#ifdef LIGHTLAB_SOURCE_DATA_DIR
  folders.emplace_back(LIGHTLAB_SOURCE_DATA_DIR "/presets/assignments");
#endif
  for (const std::string& folder : folders) {
    const fs::path p = fs::path(folder) / (assignment + ".json");
    if (fs::exists(p)) return p.lexically_normal().string();
  }
  return "";
}

std::string assignmentProblem(const std::string& assignment) {
  const auto names = assignmentNames();
  if (std::find(names.begin(), names.end(), assignment) == names.end())
    return "unknown assignment '" + assignment + "' (allowed: " + joinNames(names, ", ") + ")";
  if (assignmentPresetPath(assignment).empty())
    return "no preset for " + assignment + " (data/presets/assignments/" + assignment + ".json)";
  return "";
}

bool focusAssignment(AppState& app, const std::string& assignment, bool applyItsPreset) {
  if (const std::string problem = assignment.empty() ? "" : assignmentProblem(assignment); !problem.empty()) {
    addMessage(app, problem);
    return false;
  }
  // Undo the previous focus's references, then send the other assignments' tasks to theirs
  // (a task the user switched to its reference stays so).
  for (int t : app.focusReferences)
    if (tasks::mode(t) == tasks::Mode::Reference) tasks::setMode(t, tasks::Mode::Auto);
  app.focusReferences.clear();
  app.assignment = assignment;
  const auto catalog = tasks::taskCatalog();
  if (!assignment.empty() && tasks::modulesEnabled())
    for (size_t t = 0; t < catalog.size(); ++t) {
      const int task = static_cast<int>(t);
      if (catalog[t].assignment() == assignment || tasks::mode(task) == tasks::Mode::Reference) continue;
      tasks::setMode(task, tasks::Mode::Reference);
      app.focusReferences.push_back(task);
    }
  app.cameraChanged = true;  // every pane renders again
  if (assignment.empty() || !applyItsPreset) return true;
  return loadPresetFile(app, assignmentPresetPath(assignment));
}

}  // namespace ll::gui
