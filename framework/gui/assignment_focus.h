// Focus on one assignment (lightlab gui --assignment A2, or the side panel's
// picker): the panes open on that assignment's preset
// (data/presets/assignments/A2.json: the scene and techniques its handout
// uses, set up so they run the student's own code), the other assignments'
// tasks run their reference, and the banners and captions name only this
// assignment's tasks.
#pragma once

#include <string>
#include <vector>

#include "gui/app_state.h"

namespace ll::gui {

// "A1" ... "A6", from the task catalog.
std::vector<std::string> assignmentNames();

// Why `assignment` cannot be focused ("unknown assignment 'A9' (allowed: A1, ...)"), or "" if it can.
std::string assignmentProblem(const std::string& assignment);

// The preset of an assignment (empty if none is found), looked up like the bundled scenes.
std::string assignmentPresetPath(const std::string& assignment);

// Focuses `assignment` ("" = every assignment, no preset). Unknown names and
// preset errors become messages; returns false then.
bool focusAssignment(AppState& app, const std::string& assignment, bool applyItsPreset = true);

}  // namespace ll::gui
