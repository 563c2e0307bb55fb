#include "gui/side_panel.h"


#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>
#include <string>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "core/error.h"
#include "gui/accuracy_plot.h"
#include "gui/app_actions.h"
#include "gui/assignment_focus.h"
#include "gui/file_picker.h"
#include "gui/hot_reload.h"
#include "gui/param_widgets.h"
#include "gui/ray_inspector.h"
#include "gui/ui_scale.h"
#include "gui/view_camera.h"
#include "gui/viewport.h"
#include "modules/registry.h"
#include "tasks/task_catalog.h"
#include "tasks/task_modes.h"

namespace ll::gui {

namespace {

void helpMarker(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

void sceneSection(AppState& app) {
  if (!ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (app.scenePath.empty()) {
    ImGui::TextUnformatted("(no scene)");
  } else {  // its short name; the whole path on hover
    ImGui::TextWrapped("%s", pickerEntries({app.scenePath}).front().name.c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", app.scenePath.c_str());
  }
  if (!app.loadingPath.empty())
    ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "loading %s ...", app.loadingPath.c_str());
  if (app.scene) {
    ImGui::Text("%u triangles, %zu spheres", app.scene->geometry.triangleCount(),
                app.scene->geometry.spheres.size());
    ImGui::TextWrapped("effects: %s", joinNames(app.scene->effects.names()).c_str());
  }
  const std::vector<PickerEntry> scenes = pickerEntries(app.sceneFiles);
  const std::string chosen = pickerCombo(app, "open", "choose a scene", scenes, app.sceneSearch, "scene", app.scenePath);
  if (!chosen.empty()) openScene(app, chosen);
  helpMarker(
      "Scenes in data/scenes (bundled) and the build's generated scenes; type to search.\nYou can also drop "
      "a scene or preset file on the window.");
  ImGui::InputText("path", app.pathInput, sizeof app.pathInput);
  recordWidget(app, "scene.path");
  ImGui::SameLine();
  if (ImGui::Button("Open")) openScene(app, app.pathInput);
  recordWidget(app, "scene.open");
  if (ImGui::Button("Reload")) openScene(app, app.scenePath, true);
  ImGui::SameLine();
  ImGui::Checkbox("reload on change", &app.autoReload);
}

void cameraSection(AppState& app) {
  if (!ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) return;
  Camera c = app.camera;
  bool edited = false;
  const float step =
      app.scene ? std::max(app.scene->geometry.sceneBounds().diagonal() * 0.002f, 1e-4f) : 0.01f;
  edited |= ImGui::DragFloat3("eye", &c.eye.x, step, 0, 0, "%.3f");
  edited |= ImGui::DragFloat3("target", &c.target.x, step, 0, 0, "%.3f");
  edited |= ImGui::DragFloat3("up", &c.up.x, 0.01f, -1, 1, "%.3f");
  edited |= ImGui::SliderFloat("fov y (deg)", &c.fovYDeg, 1.0f, 150.0f, "%.1f");
  // A typed or dragged value that would make the camera unusable is not applied; the reason shows.
  std::string& refused = app.cameraRefused;
  if (edited) {
    refused = cameraProblem(c);
    if (refused.empty()) {
      app.camera = c;
      app.cameraChanged = true;
    }
  }
  if (!refused.empty()) {  // wrapped: at UI scale 2 the reason is wider than the panel
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.35f, 1.0f));
    ImGui::TextWrapped("not applied: %s", refused.c_str());
    ImGui::PopStyleColor();
  }
  if (ImGui::Button("Frame scene")) frameScene(app), refused.clear();
  recordWidget(app, "camera.frame");
  ImGui::SameLine();
  if (ImGui::Button("Reset")) resetCamera(app), refused.clear();
  helpMarker(
      "Over the image: left drag orbits, right/middle drag pans, wheel zooms.\nW/A/S/D fly, Q/E "
      "down/up, Shift = faster.");
}

void layoutSection(AppState& app) {
  if (!ImGui::CollapsingHeader("Layout and compare", ImGuiTreeNodeFlags_DefaultOpen)) return;
  int count = app.paneCount;
  ImGui::Text("panes");
  for (int n : {1, 2, 4}) {
    ImGui::SameLine();
    char label[8];
    std::snprintf(label, sizeof label, "%d", n);
    if (ImGui::RadioButton(label, count == n)) app.paneCount = n;
  }
  int mode = static_cast<int>(app.compare.mode);
  ImGui::RadioButton("side by side", &mode, 0);
  recordWidget(app, "compare.side-by-side");
  ImGui::SameLine();
  ImGui::RadioButton("wipe", &mode, 1);
  recordWidget(app, "compare.wipe");
  ImGui::SameLine();
  ImGui::RadioButton("difference", &mode, 2);
  recordWidget(app, "compare.difference");
  app.compare.mode = static_cast<CompareMode>(mode);
  const char* letters[] = {"A", "B", "C", "D"};
  if (app.compare.mode != CompareMode::SideBySide) {
    ImGui::SetNextItemWidth(uiPx(60.0f));
    ImGui::Combo("##a", &app.compare.paneA, letters, kMaxPanes);
    ImGui::SameLine();
    ImGui::Text(app.compare.mode == CompareMode::Wipe ? "left,  right" : "against");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(uiPx(60.0f));
    ImGui::Combo("##b", &app.compare.paneB, letters, kMaxPanes);
  }
  if (app.compare.mode == CompareMode::Wipe)
    ImGui::SliderFloat("split", &app.compare.wipe, 0.0f, 1.0f, "%.2f");
  if (app.compare.mode == CompareMode::Difference) {
    int diff = app.compare.diff == DiffMode::Absolute ? 0 : 1;
    ImGui::RadioButton("absolute", &diff, 0);
    ImGui::SameLine();
    ImGui::RadioButton("relative", &diff, 1);
    app.compare.diff = diff == 0 ? DiffMode::Absolute : DiffMode::Relative;
    ImGui::SliderFloat("scale max", &app.compare.diffMax, 0.0f, 1.0f,
                       app.compare.diffMax <= 0 ? "auto" : "%.4f", ImGuiSliderFlags_AlwaysClamp);
    helpMarker(
        "0 = automatic: the 99th percentile of the error, so a few fireflies do not wash out the "
        "map.");
  }
  const char* refs[] = {"none", "A", "B", "C", "D"};
  int ref = app.compare.reference + 1;
  if (ImGui::Combo("error against", &ref, refs, kMaxPanes + 1)) app.compare.reference = ref - 1;
  helpMarker(
      "RMSE and SSIM of every other pane against this reference pane, updated as passes arrive.");
  ImGui::SliderFloat("exposure", &app.exposure, -8.0f, 8.0f, "%+.1f stops");
  ImGui::Checkbox("structure", &app.showStructure);
  recordWidget(app, "structure.show");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
  ImGui::SliderInt("depth", &app.structureDepth, 0, 30, "depth %d", ImGuiSliderFlags_AlwaysClamp);
  helpMarker(
      "Draws the nodes of each pane's accelerator at this depth (boxes, cells or spheres; leaves "
      "above it in orange).");
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.0f);  // two fields of four digits
  int size[2] = {app.width, app.height};
  if (ImGui::InputInt2("render size (0 = scene)", size, ImGuiInputTextFlags_EnterReturnsTrue)) {
    app.width = std::clamp(size[0], 0, 8192);
    app.height = std::clamp(size[1], 0, 8192);
    for (PaneState& p : app.panes) p.dirty = true;
  }
}

void statsTable(const PaneState& p) {
  const PaneSnapshot& s = p.shown;
  const double rays = static_cast<double>(s.stats.work.totalRays());
  ImGui::Text("pass %d/%d   %.2f s   %.2f Mrays/s", s.passes, s.totalPasses, s.elapsed(),
              s.seconds > 0 ? rays / s.seconds / 1e6 : 0.0);
  if (ImGui::BeginTable("rays", 2,
                        ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp)) {
    for (int k = 0; k < kRayKindCount; ++k) {
      const uint64_t n = s.stats.work.rays[static_cast<size_t>(k)];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(std::string(kRayKindNames[static_cast<size_t>(k)]).c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%llu", static_cast<unsigned long long>(n));
    }
    ImGui::EndTable();
  }
  const auto& a = s.stats.accel;
  ImGui::Text("accel build %.3f s, %zu nodes, depth %d, %.1f KiB", s.buildSeconds, a.nodeCount, a.depth,
              static_cast<double>(a.memoryBytes) / 1024.0);
  if (a.sahCost > 0.0) ImGui::Text("SAH cost %.2f", a.sahCost);
  if (s.stats.work.query.nodesVisited + s.stats.work.query.primitivesTested > 0 && rays > 0)
    ImGui::Text("per ray: %.1f nodes visited, %.1f primitives tested",
                static_cast<double>(s.stats.work.query.nodesVisited) / rays,
                static_cast<double>(s.stats.work.query.primitivesTested) / rays);
  if (s.stats.work.nonFinite > 0)
    ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%llu NaN/Inf samples replaced by 0",
                       static_cast<unsigned long long>(s.stats.work.nonFinite));
}

void paneSection(AppState& app, int i) {
  PaneState& p = app.panes[static_cast<size_t>(i)];
  char title[96];
  std::snprintf(title, sizeof title, "Pane %c: %s / %s###pane%d", paneLetter(i),
                p.technique.c_str(), p.accelerator.c_str(), i);
  if (!ImGui::CollapsingHeader(title, i < 2 ? ImGuiTreeNodeFlags_DefaultOpen : 0)) return;
  ImGui::PushID(i);
  const std::string letter(1, paneLetter(i));
  if (ImGui::BeginCombo("technique", p.technique.c_str())) {
    recordWindow(app, letter + ".technique.list");
    for (const TechniqueInfo& t : techniques()) {
      if (ImGui::Selectable(t.name.c_str(), t.name == p.technique)) setTechnique(app, i, t.name);
      recordWidget(app, letter + ".technique:" + t.name);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", t.help.c_str());
    }
    ImGui::EndCombo();
  }
  recordWidget(app, letter + ".technique");
  if (ImGui::BeginCombo("accelerator", p.accelerator.c_str())) {
    for (const AcceleratorInfo& a : accelerators()) {
      if (ImGui::Selectable(a.name.c_str(), a.name == p.accelerator))
        setAccelerator(app, i, a.name);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", a.help.c_str());
    }
    ImGui::EndCombo();
  }
  if (ImGui::SliderInt("passes (spp)", &p.spp, 1, 1024, "%d",
                       ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
    p.dirty = true;
  if (paramWidgets(p.techniqueParams, [&](const std::string& name) {
        recordWidget(app, letter + ".param." + name);
      }))
    p.dirty = true;
  if (!p.accelParams.decls().empty() && ImGui::TreeNode("accelerator parameters")) {
    if (paramWidgets(p.accelParams)) p.dirty = true;
    ImGui::TreePop();
  }
  const char* views[] = {"image", "cost: nodes visited", "cost: primitives tested", "light paths (path, radiosity)"};
  int view = static_cast<int>(p.view);
  if (ImGui::Combo("view", &view, views, 4)) {
    p.view = static_cast<PaneView>(view);
    p.dirty = true;
  }
  recordWidget(app, letter + ".view");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "cost: the accelerator's work for the camera ray of each pixel, as a heatmap with its "
        "scale");
  if (ImGui::Button("Restart")) p.dirty = true;
  if (app.scene) {
    const TechniqueInfo& info = findTechnique(p.technique);
    const EffectSet sim = info.simulatesIn(*app.scene, p.techniqueParams);
    const EffectSet needed = app.scene->effects;
    ImGui::TextWrapped("simulates: %s",
                       joinNames(EffectSet::fromBits(needed.bits() & sim.bits()).names()).c_str());
    const EffectSet missed = needed.minus(sim);
    // The light-path view's numbers in full (the tiles' labels drop the relMSE where it does not fit).
    if (p.shown.view == PaneView::LightPaths && p.shown.lightPathTiles.size() > 1 &&
        ImGui::BeginTable("lightpaths", 3, ImGuiTableFlags_SizingStretchProp)) {
      ImGui::TableNextRow();
      for (const char* head : {"light path", "share", "relMSE without"}) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(head);
      }
      for (const MosaicTile& t : p.shown.lightPathTiles) {
        if (t.share < 0.0) continue;
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(t.name.c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(t.shareText().c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%.2g", t.relMseWithout);
      }
      ImGui::EndTable();
    }
    if (!missed.empty())
      ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "misses: %s%s", joinNames(missed.names()).c_str(),
                         info.lightsNote(*app.scene));
  }
  statsTable(p);
  if (p.hasError)
    ImGui::Text("vs %c: RMSE %.5g  SSIM %.4f  PSNR %.2f dB", paneLetter(app.compare.reference),
                p.error.rmse, p.error.ssim, p.error.psnr);
  for (const auto& [id, what] : p.shown.missingTasks)
    ImGui::TextColored(ImVec4(1, 0.4f, 0.9f, 1), "task %s missing: %s", id.c_str(), what.c_str());
  if (p.shown.phase == PaneSnapshot::Phase::Failed)
    ImGui::TextColored(ImVec4(1, 0.3f, 0.3f, 1), "%s", p.shown.error.c_str());
  ImGui::PopID();
}

// The student tree, at the top: the assignment in focus, the hot-reload
// status (build errors), and per task your code or its reference (the same
// switch as --reference).
void yourCodeSection(AppState& app) {
  // The solution tree has no student code: only the assignment picker.
  const bool student = tasks::modulesEnabled();
  if (!ImGui::CollapsingHeader(student ? "Your code" : "Assignment", student ? ImGuiTreeNodeFlags_DefaultOpen : 0)) return;
  const std::string current = app.assignment.empty() ? std::string("all") : app.assignment;
  if (ImGui::BeginCombo("assignment", current.c_str())) {
    recordWindow(app, "assignment.list");
    if (ImGui::Selectable("all", app.assignment.empty())) focusAssignment(app, "");
    recordWidget(app, "assignment:all");
    for (const std::string& a : assignmentNames()) {
      if (ImGui::Selectable(a.c_str(), a == app.assignment)) focusAssignment(app, a);
      recordWidget(app, "assignment:" + a);
    }
    ImGui::EndCombo();
  }
  recordWidget(app, "assignment");
  helpMarker("Focus on one assignment: its scene and techniques (the handout's), its tasks in the banners,\n"
             "every other assignment's tasks by their reference.");
  if (!student) return;
  drawHotReloadStatus(app);

  std::set<std::string> missing, violations, ran;
  for (int i = 0; i < kMaxPanes; ++i)
    if (paneActive(app, i)) {
      for (const auto& [id, what] : app.panes[static_cast<size_t>(i)].shown.missingTasks) missing.insert(id);
      for (const auto& [id, what] : app.panes[static_cast<size_t>(i)].shown.taskViolations) violations.insert(id);
      for (const auto& [id, byReference] : app.panes[static_cast<size_t>(i)].shown.tasksRan) ran.insert(id);
    }
  ImGui::TextDisabled("Tick a task to see its reference:");
  helpMarker(
      "Each task runs your code, or the course's reference (object code in assignments/reference/lib).\n"
      "Where your function is still a stub, its reference stands in and striped pixels mark it.\n"
      "Tick a task to see its reference instead of your code (lightlab --reference ID on the command line).");
  std::string assignment;
  bool open = false;
  const auto catalog = tasks::taskCatalog();
  for (size_t t = 0; t < catalog.size(); ++t) {
    const tasks::TaskInfo& info = catalog[t];
    if (info.assignment() != assignment) {
      if (open) ImGui::TreePop();
      assignment = info.assignment();
      // Open the assignment in focus, and where the panes use an assignment's tasks (a stub or a rule broken).
      bool used = assignment == app.assignment;
      for (const std::string& id : missing) used = used || id.rfind(assignment + ".", 0) == 0;
      for (const std::string& id : violations) used = used || id.rfind(assignment + ".", 0) == 0;
      if (used) ImGui::SetNextItemOpen(true, ImGuiCond_Once);
      open = ImGui::TreeNode(assignment.c_str());
    }
    if (!open) continue;
    bool reference = tasks::mode(static_cast<int>(t)) == tasks::Mode::Reference;
    ImGui::PushID(static_cast<int>(t));
    if (ImGui::Checkbox("##reference", &reference)) {
      tasks::setMode(static_cast<int>(t), reference ? tasks::Mode::Reference : tasks::Mode::Auto);
      app.cameraChanged = true;  // every pane renders again
      addMessage(app, std::string(info.id) + (reference ? ": the reference" : ": your code"), false);
    }
    recordWidget(app, std::string("task:") + info.id);
    ImGui::SameLine();
    // "yours" only for code the panes ran: a stub the panes never call is not known to be one.
    const char* state = reference                ? "reference"
                        : violations.count(info.id) ? "breaks a rule"
                        : missing.count(info.id)    ? "stub (reference shown)"
                        : ran.count(info.id)        ? "yours"
                                                     : "not run by these panes";
    const ImVec4 colour = reference                  ? ImVec4(0.6f, 0.8f, 1, 1)
                          : violations.count(info.id) ? ImVec4(1, 0.4f, 0.4f, 1)
                          : missing.count(info.id)    ? ImVec4(1, 0.4f, 0.9f, 1)
                          : ran.count(info.id)        ? ImVec4(0.6f, 1, 0.6f, 1)
                                                       : ImVec4(0.6f, 0.6f, 0.65f, 1);
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextWrapped("%s %s: %s", info.id, info.title, state);
    ImGui::PopStyleColor();
    ImGui::PopID();
  }
  if (open) ImGui::TreePop();
}

void lectureHallSection(AppState& app) {
  if (!ImGui::CollapsingHeader("Lecture hall")) return;
  ImGui::Checkbox("projector labels (P)", &app.projector);
  recordWidget(app, "hall.projector");
  helpMarker(
      "One line per pane in large type, naming only what differs between the panes (technique, "
      "accelerator, 'depth 2', '64 spp'). On by default in presenter mode.");
  ImGui::Checkbox("stats under the labels (I)", &app.showStats);
  if (ImGui::Button("Hide this panel (H)")) {
    app.panelHidden = true;
    app.panelHiddenAt = std::chrono::steady_clock::now();
  }
  recordWidget(app, "hall.hide");
  ImGui::Checkbox("cost-of-accuracy plot", &app.showPlot);
  recordWidget(app, "hall.plot");
  helpMarker(
      "Every pane's error (relMSE) against the reference pane over its wall time, both on log "
      "scales: the price of accuracy, technique by technique. A preset asks for it with \"plot\": true.");
  if (app.showPlot && app.compare.reference < 0) {
    ImGui::TextColored(ImVec4(1, 0.8f, 0.4f, 1), "The plot needs a reference pane:");
    if (ImGui::Button("measure against the last pane")) app.compare.reference = app.paneCount - 1;
  }
  static char plotPath[256] = "accuracy_plot";
  ImGui::InputText("plot file", plotPath, sizeof plotPath);
  if (ImGui::Button("Save SVG")) {
    const std::string path = std::string(plotPath) + ".svg";
    try {
      saveAccuracyPlotSvg(accuracyPlot(app), path);
      addMessage(app, "plot " + path, false);
    } catch (const std::exception& e) {
      addMessage(app, e.what());
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Save PNG")) {
    if (!app.showPlot) addMessage(app, "show the plot first: the PNG is its pixels on screen");
    else app.plotPngRequest = std::string(plotPath) + ".png";
  }
}

void presetSection(AppState& app) {
  if (!ImGui::CollapsingHeader("Preset")) return;
  const std::vector<PickerEntry> presets = pickerEntries(app.presetFiles);
  const std::string chosen = pickerCombo(app, "open##preset", "choose a preset", presets, app.presetSearch, "preset", "");
  if (!chosen.empty() && loadPresetFile(app, chosen))
    std::snprintf(app.presetInput, sizeof app.presetInput, "%s", chosen.c_str());
  helpMarker("The bundled demos (data/presets) and each assignment's views; type to search.");
  ImGui::InputText("file", app.presetInput, sizeof app.presetInput);
  if (ImGui::Button("Save")) savePresetFile(app, app.presetInput);
  ImGui::SameLine();
  if (ImGui::Button("Load")) loadPresetFile(app, app.presetInput);
  helpMarker(
      "The whole view: scene, camera, panes with technique, accelerator and parameters, compare "
      "mode.\nOpen one with `lightlab gui --preset FILE`.");
}

void viewSection(AppState& app, GLFWwindow* window) {
  if (!ImGui::CollapsingHeader("View")) return;
  ImGui::SliderFloat("UI scale", &app.uiScale, 0.5f, 3.0f, "%.2f");
  ImGui::Text("monitor content scale %.2f", static_cast<double>(app.contentScale));
  const float fps = ImGui::GetIO().Framerate;
  ImGui::Text("UI %.1f ms per frame (%.0f fps)",
              static_cast<double>(1000.0f / std::max(fps, 1e-3f)), static_cast<double>(fps));
  const FrameTimes& ft = app.uiFrameWork;
  if (ft.frames > 1)
    ImGui::Text("UI work per frame: mean %.2f ms, max %.1f ms",
                1e3 * ft.sumSeconds / (ft.frames - 1), 1e3 * ft.maxSeconds);
  helpMarker(
      "The UI never waits for a render: panes render on worker threads and the UI only copies "
      "finished passes.");
  if (ImGui::Button(app.fullscreen ? "Windowed (F11)" : "Fullscreen (F11)"))
    toggleFullscreen(app, window);
  ImGui::SameLine();
  if (ImGui::Button("Screenshot (F12)")) app.screenshotRequest = "lightlab_screenshot.png";
}

void messagesSection(AppState& app) {
  if (!ImGui::CollapsingHeader("Messages", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (ImGui::SmallButton("clear")) app.messages.clear();
  for (auto it = app.messages.rbegin(); it != app.messages.rend(); ++it)
    ImGui::TextColored(it->error ? ImVec4(1, 0.45f, 0.45f, 1) : ImVec4(0.7f, 0.9f, 0.7f, 1), "%s",
                       it->text.c_str());
}

}  // namespace

// Remembers the visible content area of the current window (the panel, or an
// open combo's list: no title bar, padding or scrolled-out part), under `name`.
void recordWindow(AppState& app, const std::string& name) {
  const ImVec2 pos = ImGui::GetWindowPos(), scroll(ImGui::GetScrollX(), ImGui::GetScrollY());
  const ImVec2 a = ImGui::GetWindowContentRegionMin(), b = ImGui::GetWindowContentRegionMax();
  app.widgetRects[name] = {pos.x + a.x + scroll.x, pos.y + a.y + scroll.y, b.x - a.x, b.y - a.y};
}

void recordWidget(AppState& app, const std::string& name) {
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  app.widgetRects[name] = {a.x, a.y, b.x - a.x, b.y - a.y};
}

void toggleFullscreen(AppState& app, GLFWwindow* window) {
  if (!app.fullscreen) {
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
    if (!mode) return;
    glfwGetWindowPos(window, &app.windowedPos[0], &app.windowedPos[1]);
    glfwGetWindowSize(window, &app.windowedSize[0], &app.windowedSize[1]);
    glfwSetWindowMonitor(window, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
  } else {
    glfwSetWindowMonitor(window, nullptr, app.windowedPos[0], app.windowedPos[1],
                         app.windowedSize[0], app.windowedSize[1], 0);
  }
  app.fullscreen = !app.fullscreen;
}

void drawSidePanel(AppState& app, GLFWwindow* window, float width, float height) {
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(width, height));
  ImGui::Begin("LightLab", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  app.widgetRects.clear();  // only what this frame draws
  recordWindow(app, "panel");
  ImGui::PushItemWidth(-ImGui::GetFontSize() * 9.0f);
  yourCodeSection(app);
  sceneSection(app);
  cameraSection(app);
  layoutSection(app);
  lectureHallSection(app);
  for (int i = 0; i < kMaxPanes; ++i)
    if (paneActive(app, i)) paneSection(app, i);
  rayTreeSection(app);
  presetSection(app);
  viewSection(app, window);
  messagesSection(app);
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace ll::gui
