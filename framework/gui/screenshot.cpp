#include "gui/screenshot.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

#include <GL/gl.h>
#include <stb/stb_image_write.h>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "gui/app_actions.h"
#include "gui/viewport.h"

namespace ll::gui {

namespace {

// The light-path view's tiles: label and rectangle in the pane's image pixels.
nlohmann::json lightPathTilesJson(const std::vector<MosaicTile>& tiles) {
  nlohmann::json out = nlohmann::json::array();
  for (const MosaicTile& t : tiles)
    out.push_back({{"label", t.label()}, {"name", t.name}, {"share", t.share}, {"x", t.x}, {"y", t.y}, {"w", t.w},
                   {"h", t.h}});
  return out;
}

}  // namespace

void saveFramebufferPng(const std::string& path, int width, int height) {
  saveFramebufferRegionPng(path, height, 0, 0, width, height);
}

void saveFramebufferRegionPng(const std::string& path, int framebufferHeight, int x, int y, int width, int height) {
  if (width <= 0 || height <= 0) throwUserError(path + ": nothing to save (the region is empty)");
  std::vector<uint8_t> pixels(static_cast<size_t>(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  // GL rows go bottom-up from the framebuffer's bottom; PNG rows top-down. The window is opaque.
  glReadPixels(x, framebufferHeight - y - height, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  std::vector<uint8_t> flipped(pixels.size());
  const size_t row = static_cast<size_t>(width) * 4;
  for (int r = 0; r < height; ++r)
    for (size_t i = 0; i < row; ++i)
      flipped[static_cast<size_t>(r) * row + i] =
          (i % 4 == 3) ? 255 : pixels[static_cast<size_t>(height - 1 - r) * row + i];
  if (!stbi_write_png(path.c_str(), width, height, 4, flipped.data(), static_cast<int>(row)))
    throwUserError(path + ": cannot write the PNG");
}

std::string saveScreenshotSidecar(const AppState& app, const std::string& path, int width,
                                  int height, float pixelScale) {
  using nlohmann::json;
  const auto rect = [&](const std::array<float, 4>& r) {
    return json::array(
        {r[0] * pixelScale, r[1] * pixelScale, r[2] * pixelScale, r[3] * pixelScale});
  };
  static const char* kPhases[] = {"idle", "building", "rendering", "done", "failed", "stopped"};
  json j{{"width", width},
         {"height", height},
         {"scene", app.scenePath},
         {"pane_count", app.paneCount}};
  j["panes"] = json::array();
  for (int i = 0; i < kMaxPanes; ++i) {
    const PaneState& p = app.panes[static_cast<size_t>(i)];
    json pj{{"index", i},
            {"technique", p.technique},
            {"accelerator", p.accelerator},
            {"phase", kPhases[static_cast<int>(p.shown.phase)]},
            {"passes", p.shown.passes},
            {"total_passes", p.shown.totalPasses},
            {"starts", p.shown.starts},
            {"image_version", p.shown.version},
            // The version the pixels on screen show: behind image_version until the
            // background worker's display bytes are uploaded.
            {"on_screen_version", p.texture.version()},
            {"rect", rect(app.paneRects[static_cast<size_t>(i)])},
            {"missing_tasks", p.shown.missingTasks},
            {"task_violations", p.shown.taskViolations},
            {"tasks_ran", p.shown.tasksRan},  // task id -> answered by the reference
            {"error", p.shown.error},
            {"params", p.techniqueParams.toJson()},
            {"view", viewName(p.view)},
            {"legend_max", p.texture.legendMax()},
            {"structure_nodes", app.showStructure ? p.overlayNodes.size() : 0},
            {"light_path_tiles", lightPathTilesJson(p.shown.lightPathTiles)},
            {"accel_params", p.accelParams.toJson()},
            {"phase_name", p.shown.phaseName},
            {"phase_fraction", p.shown.phaseFraction},
            {"phases_drawn", p.phasesDrawn},
            {"seconds", p.shown.seconds},
            {"elapsed", p.shown.elapsed()},
            // Whether the pane's picture is on screen (false: the neutral placeholder while it has none
            // of its current technique).
            {"image_on_screen", imageOnScreen(p)},
            {"request_current", p.shown.request == p.submitted},  // the worker reports on the last submit
            {"image_shows", p.shown.imageShows},
            {"error_history", p.errorHistory}};
    if (p.shown.image) pj["image_size"] = {p.shown.image->width(), p.shown.image->height()};
    pj["striped"] = p.shown.unstriped != nullptr;  // the picture has stub stripes
    // Against the reference pane, as the caption's "vs B" line (null while not measured).
    pj["vs_reference"] = p.hasError ? json{{"relmse", p.error.relmse}, {"rmse", p.error.rmse}, {"ssim", p.error.ssim}}
                                    : json(nullptr);
    j["panes"].push_back(pj);
  }
  j["compare"] = {{"mode", compareModeName(app.compare.mode)},
                  {"a", app.compare.paneA},
                  {"b", app.compare.paneB},
                  {"wipe", app.compare.wipe},
                  {"rect", rect(app.compareRect)},
                  {"diff_max", app.diff.usedMax}};
  const auto vec = [](const Vec3& v) { return json::array({v.x, v.y, v.z}); };
  if (app.inspector.pane >= 0)
    j["ray_tree"] = {{"pane", app.inspector.pane},
                     {"pixel", {app.inspector.pixel.x, app.inspector.pixel.y}},
                     {"nodes", app.inspector.tree ? app.inspector.tree->nodes.size() : 0},
                     {"note", app.inspector.note}};
  if (app.presenter.active()) {
    const PresenterState& p = app.presenter;
    const Slide& slide = p.deck->slides[static_cast<size_t>(p.index)];
    j["slides"] = {{"deck", p.deck->path},
                   {"index", p.index},
                   {"count", p.count()},
                   {"anchor", slide.anchor},
                   {"applied", p.applied},
                   {"preset", slide.preset ? slide.preset->source : ""}};
  }
  j["camera"] = {{"eye", vec(app.camera.eye)},
                 {"target", vec(app.camera.target)},
                 {"up", vec(app.camera.up)},
                 {"fov_y_deg", app.camera.fovYDeg}};
  const FrameTimes& ft = app.uiFrameWork;
  j["ui_frames"] = {{"count", ft.frames},
                    {"first_frame_ms", 1e3 * ft.firstSeconds},
                    {"mean_work_ms", ft.frames > 1 ? 1e3 * ft.sumSeconds / (ft.frames - 1) : 0.0},
                    {"max_work_ms", 1e3 * ft.maxSeconds}};
  j["assignment"] = app.assignment;
  const HotReloadState& h = app.hotReload;
  j["reload"] = {{"phase", hotReloadPhaseName(h.phase)},
                 {"reloads", h.reloads},
                 {"error", h.phase == HotReloadState::Phase::Failed ? h.last.firstError.oneLine() : ""},
                 {"build_seconds", h.buildSeconds},
                 {"latency_seconds", h.latencySeconds}};
  j["projector"] = {{"on", app.projector}, {"stats", app.showStats}, {"panel_hidden", app.panelHidden},
                    {"labels", app.paneLabels}};
  j["projector"]["label_rects"] = json::array();
  for (const auto& r : app.labelRects) j["projector"]["label_rects"].push_back(rect(r));
  j["plot"] = {{"shown", app.showPlot}, {"rect", rect(app.plotRect)}};
  j["widgets"] = json::object();
  for (const auto& [name, r] : app.widgetRects) j["widgets"][name] = rect(r);
  j["overlays"] = json::array();
  for (const auto& r : app.overlayRects) j["overlays"].push_back(rect(r));
  j["messages"] = json::array();
  for (const Message& m : app.messages)
    j["messages"].push_back({{"text", m.text}, {"error", m.error}});
  const std::string sidecar = std::filesystem::path(path).replace_extension(".json").string();
  std::ofstream out(sidecar);
  if (!out) throwUserError(sidecar + ": cannot write screenshot sidecar");
  // Bytes that are not UTF-8 (a Latin-1 file name or message) become U+FFFD instead of ending the program.
  out << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  return sidecar;
}

}  // namespace ll::gui
