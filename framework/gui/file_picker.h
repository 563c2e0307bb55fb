// The scene and preset pickers: short names (relative to data/), bundled
// files first, then the build's generated ones, grouped, filtered by a search
// field. The entries are pure (unit-tested); pickerCombo draws them with ImGui.
#pragma once

#include <string>
#include <vector>

#include "gui/app_state.h"

namespace ll::gui {

struct PickerEntry {
  std::string path;   // as opened
  std::string name;   // shown: relative to the data/ folder it is in ("scenes/cornell_box.json")
  std::string group;  // "bundled scenes", "generated scenes (build)", "presets", "assignment presets", "other"
};

// Entries for `files`, sorted: group by group (bundled before generated),
// then by name. A file under several data/ folders appears once.
std::vector<PickerEntry> pickerEntries(const std::vector<std::string>& files);

// Whether `entry` matches the search text: every space-separated word occurs
// in its name (case-insensitive). An empty search matches everything.
bool pickerMatches(const PickerEntry& entry, const std::string& search);

// View presets (JSON with "lightlab_preset") under `folders`, recursively.
std::vector<std::string> findPresetFiles(const std::vector<std::string>& folders);

// A combo box listing `entries` under their group headings with a search field
// on top. Recorded widgets: the combo `<widget>.files`, its list
// `<widget>.files.list`, the search field `<widget>.files.search`, each file
// `<widget>.file:<path>`. Returns the chosen path, or an empty string.
std::string pickerCombo(AppState& app, const char* label, const char* preview,
                        const std::vector<PickerEntry>& entries, std::string& search, const std::string& widget,
                        const std::string& current);

}  // namespace ll::gui
