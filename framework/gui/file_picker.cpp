#include "gui/file_picker.h"

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <cctype>
#include <filesystem>
#include <set>
#include <sstream>

#include <imgui.h>

#include "gui/app_actions.h"
#include "gui/side_panel.h"

namespace ll::gui {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Rank of a group in the list: bundled scenes first.
int groupRank(const std::string& group) {
  static const std::vector<std::string> kOrder{"bundled scenes", "presets", "assignment presets",
                                               "generated scenes (build)", "other"};
  const auto it = std::find(kOrder.begin(), kOrder.end(), group);
  return static_cast<int>(it - kOrder.begin());
}

}  // namespace

std::vector<PickerEntry> pickerEntries(const std::vector<std::string>& files) {
  std::vector<PickerEntry> out;
  std::set<std::string> seen;  // group + name: the same file found through two folders
  for (const std::string& path : files) {
    const fs::path p = fs::path(path).lexically_normal();
    // The part after the last "data" folder, and whether a "build" folder comes before it.
    std::vector<std::string> parts;
    for (const auto& part : p) parts.push_back(part.string());
    size_t data = parts.size();
    for (size_t i = 0; i + 1 < parts.size(); ++i)
      if (parts[i] == "data") data = i;
    const bool generated = std::find(parts.begin(), parts.begin() + static_cast<long>(std::min(data, parts.size())),
                                     "build") != parts.begin() + static_cast<long>(std::min(data, parts.size()));
    PickerEntry e;
    e.path = path;
    if (data < parts.size()) {
      fs::path rel;
      for (size_t i = data + 1; i < parts.size(); ++i) rel /= parts[i];
      e.name = rel.generic_string();
    } else {
      e.name = p.filename().string();
    }
    const bool preset = e.name.rfind("presets/", 0) == 0;
    e.group = preset ? (e.name.rfind("presets/assignments/", 0) == 0 ? "assignment presets" : "presets")
              : data == parts.size() ? "other"
              : generated            ? "generated scenes (build)"
                                     : "bundled scenes";
    if (!seen.insert(e.group + "|" + e.name).second) continue;
    out.push_back(std::move(e));
  }
  std::sort(out.begin(), out.end(), [](const PickerEntry& a, const PickerEntry& b) {
    const int ga = groupRank(a.group), gb = groupRank(b.group);
    return ga != gb ? ga < gb : a.name < b.name;
  });
  return out;
}

bool pickerMatches(const PickerEntry& entry, const std::string& search) {
  const std::string name = lower(entry.name);
  std::istringstream words(lower(search));
  for (std::string w; words >> w;)
    if (name.find(w) == std::string::npos) return false;
  return true;
}

std::vector<std::string> findPresetFiles(const std::vector<std::string>& folders) {
  std::vector<std::string> files;
  for (const std::string& folder : folders) {
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(folder, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec)) {
      std::error_code fileEc;
      if (!it->is_regular_file(fileEc) || it->path().extension() != ".json") continue;
      if (isPresetFile(it->path().string())) files.push_back(it->path().lexically_normal().string());
    }
  }
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());
  return files;
}

std::string pickerCombo(AppState& app, const char* label, const char* preview,
                        const std::vector<PickerEntry>& entries, std::string& search, const std::string& widget,
                        const std::string& current) {
  std::string chosen;
  const float rows = 14.0f;  // visible rows before the list scrolls
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(FLT_MAX, ImGui::GetTextLineHeightWithSpacing() * rows));
  if (ImGui::BeginCombo(label, preview, ImGuiComboFlags_HeightLargest)) {
    recordWindow(app, widget + ".files.list");
    char buf[128];
    std::snprintf(buf, sizeof buf, "%s", search.c_str());
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::InputTextWithHint("##search", "search", buf, sizeof buf)) search = buf;
    recordWidget(app, widget + ".files.search");
    std::string group;
    for (const PickerEntry& e : entries) {
      if (!pickerMatches(e, search)) continue;
      if (e.group != group) {
        group = e.group;
        ImGui::Spacing();
        ImGui::TextDisabled("%s", group.c_str());
        ImGui::Separator();
      }
      if (ImGui::Selectable(e.name.c_str(), e.path == current)) chosen = e.path;
      recordWidget(app, widget + ".file:" + e.path);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.path.c_str());
    }
    ImGui::EndCombo();
  }
  recordWidget(app, widget + ".files");
  return chosen;
}

}  // namespace ll::gui
