#include "gui/app_actions.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <system_error>
#include <thread>

#include "core/files.h"
#include "core/error.h"
#include "gui/pane_labels.h"
#include "gui/view_camera.h"
#include "modules/registry.h"
#include "render/cost_image.h"
#include "scene/scene_loader.h"

namespace ll::gui {

namespace fs = std::filesystem;

namespace {
using Clock = std::chrono::steady_clock;
}  // namespace

bool isPresetFile(const std::string& path) {
  if (fs::path(path).extension() != ".json") return false;
  std::ifstream in(path);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  return head.find("\"lightlab_preset\"") != std::string::npos;
}

void initPanes(AppState& app) {
  // The lecture's arc, each showing a first picture after one pass. Radiosity is not among them: it
  // solves before its first picture (minutes on a 235k-triangle mesh), so it runs only when chosen.
  static const char* const kDefaults[kMaxPanes] = {"blinn-phong", "raycast", "whitted", "path"};
  const auto& techs = techniques();
  const auto& accels = accelerators();
  for (int i = 0; i < kMaxPanes; ++i) {
    const bool known = std::any_of(techs.begin(), techs.end(), [&](const TechniqueInfo& t) { return t.name == kDefaults[i]; });
    setTechnique(app, i, known ? kDefaults[i] : techs[std::min(static_cast<size_t>(i), techs.size() - 1)].name);
    setAccelerator(app, i, accels.size() > 1 ? accels[1].name : accels[0].name);
  }
}

const char* viewName(PaneView view) {
  switch (view) {
    case PaneView::NodesVisited:
      return "nodes";
    case PaneView::PrimitivesTested:
      return "primitives";
    case PaneView::LightPaths:
      return "light-paths";
    case PaneView::Image:
      break;
  }
  return "image";
}

PaneView viewFromName(const std::string& name) {
  if (name == "nodes") return PaneView::NodesVisited;
  if (name == "primitives") return PaneView::PrimitivesTested;
  if (name == "light-paths") return PaneView::LightPaths;
  return PaneView::Image;
}

void addMessage(AppState& app, const std::string& text, bool error) {
  app.messages.push_back({text, error, Clock::now()});
  if (app.messages.size() > 50) app.messages.erase(app.messages.begin());
}

void openScene(AppState& app, const std::string& path, bool keepCamera) {
  if (app.loading.valid()) app.abandonedLoads.push_back(std::move(app.loading));
  app.loadingPath = path;
  // The time before reading: a save made while the load runs is newer, so the watcher picks it up.
  app.loadingWriteTime = writeTime(path);
  app.loadKeepsCamera = keepCamera;
  app.loading = std::async(std::launch::async, [path]() -> std::shared_ptr<const Scene> {
    return std::make_shared<Scene>(loadScene(path));
  });
}

void pollSceneLoad(AppState& app) {
  std::erase_if(app.abandonedLoads, [](const std::future<std::shared_ptr<const Scene>>& f) {
    return f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
  });
  if (!app.loading.valid() ||
      app.loading.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
    return;
  const std::string path = app.loadingPath;
  app.loadingPath.clear();
  try {
    std::shared_ptr<const Scene> scene = app.loading.get();
    const bool sameFile = path == app.scenePath;
    app.scene = std::move(scene);
    app.scenePath = path;
    ++app.sceneVersion;
    if (!app.loadKeepsCamera || !cameraIsValid(app.camera)) app.camera = app.scene->camera;
    app.cameraChanged = true;
    for (PaneState& p : app.panes) p.dirty = true;
    addMessage(app, (sameFile ? "reloaded " : "opened ") + path, false);
    if (!sameFile) std::snprintf(app.pathInput, sizeof app.pathInput, "%s", path.c_str());  // the field follows
  } catch (const std::exception& e) {  // the previous scene stays usable
    addMessage(app, e.what());
  }
  // Remember the file's time even on failure, so a broken file is not reloaded in a loop.
  if (app.scenePath == path) {
    app.sceneWriteTime = app.loadingWriteTime;
    app.sceneFileMissing = false;
  }
}

void watchSceneFile(AppState& app) {
  if (!app.autoReload || app.scenePath.empty() || !app.loadingPath.empty()) return;
  const auto now = Clock::now();
  if (now - app.lastWatch < std::chrono::milliseconds(500)) return;
  app.lastWatch = now;
  const auto t = writeTime(app.scenePath);
  if (t == fs::file_time_type{}) {
    if (!app.sceneFileMissing)
      addMessage(app, app.scenePath + ": the scene file is gone (deleted or renamed); the scene shown stays, "
                                      "and reloads when the file is back");
    app.sceneFileMissing = true;
    return;
  }
  if (t != app.sceneWriteTime || app.sceneFileMissing) openScene(app, app.scenePath, true);
}

void waitForSceneLoad(AppState& app) {
  if (app.loading.valid()) app.loading.wait();
  pollSceneLoad(app);
}

void openDroppedFile(AppState& app, const std::string& path) {
  if (isPresetFile(path))
    loadPresetFile(app, path);
  else
    openScene(app, path);
}

namespace {
// Switches a pane's module (technique or accelerator) by name. Each module
// keeps its own values: the current ones are put aside under the current name,
// and the new module gets its own from before, or its defaults -- never
// another module's (whitted's max_depth 5 is not path's).
template <class Info>
void switchModule(AppState& app, const std::string& name, const Info& (*find)(const std::string&),
                  const char* kind, std::string& current, ParamSet& params,
                  std::map<std::string, ParamSet>& saved, bool& dirty) {
  try {
    const Info& info = find(name);
    dirty = true;
    ParamSet fresh(std::string(kind) + " '" + info.name + "'", info.params);
    if (info.name == current) {  // the same module: its values stay (over fresh declarations)
      for (const ParamDecl& d : fresh.decls())
        if (params.has(d.name)) fresh.set(d.name, params.text(d.name));
      params = std::move(fresh);
      return;
    }
    if (!current.empty() && !params.decls().empty()) saved.insert_or_assign(current, params);  // (none yet: a new pane)
    const auto it = saved.find(info.name);
    params = it != saved.end() ? it->second : std::move(fresh);
    current = info.name;
  } catch (const UserError& e) {
    addMessage(app, e.what());
  }
}
}  // namespace

void setTechnique(AppState& app, int paneIndex, const std::string& name) {
  PaneState& pane = app.panes.at(static_cast<size_t>(paneIndex));
  switchModule<TechniqueInfo>(app, name, &findTechnique, "technique", pane.technique,
                              pane.techniqueParams, pane.savedTechniqueParams, pane.dirty);
}

void setAccelerator(AppState& app, int paneIndex, const std::string& name) {
  PaneState& pane = app.panes.at(static_cast<size_t>(paneIndex));
  switchModule<AcceleratorInfo>(app, name, &findAccelerator, "accelerator", pane.accelerator,
                                pane.accelParams, pane.savedAccelParams, pane.dirty);
}

void applyPreset(AppState& app, const ViewPreset& preset) {
  // Validate everything first, so a bad preset changes nothing.
  std::array<PaneState, kMaxPanes> panes;
  try {
    for (int i = 0; i < kMaxPanes; ++i) {
      const PaneSetup& setup = preset.panes.at(static_cast<size_t>(i));
      PaneState& p = panes[static_cast<size_t>(i)];
      const TechniqueInfo& t = findTechnique(setup.technique);
      const AcceleratorInfo& a = findAccelerator(setup.accelerator);
      p.technique = t.name;
      p.accelerator = a.name;
      p.techniqueParams = ParamSet("technique '" + t.name + "'", t.params);
      p.accelParams = ParamSet("accelerator '" + a.name + "'", a.params);
      for (const auto& [k, v] : setup.techniqueParams) p.techniqueParams.set(k, v);
      for (const auto& [k, v] : setup.accelParams) p.accelParams.set(k, v);
      p.spp = setup.spp;
      p.view = viewFromName(setup.view);
      p.label = setup.label;
    }
  } catch (const std::exception& e) {
    addMessage(app, std::string("preset not applied: ") + e.what());
    return;
  }
  for (int i = 0; i < kMaxPanes; ++i) {
    PaneState& dst = app.panes[static_cast<size_t>(i)];
    PaneState& src = panes[static_cast<size_t>(i)];
    dst.technique = src.technique;
    dst.accelerator = src.accelerator;
    dst.techniqueParams = src.techniqueParams;
    dst.accelParams = src.accelParams;
    dst.savedTechniqueParams.clear();  // a preset is a whole new view
    dst.savedAccelParams.clear();
    dst.spp = src.spp;
    dst.view = src.view;
    dst.label = src.label;
    dst.labelFor = paneSettings(dst);
    dst.dirty = true;
  }
  app.paneCount = preset.paneCount;
  app.compare = preset.compare;
  app.width = preset.width;
  app.height = preset.height;
  app.exposure = preset.exposure;
  app.uiScale = preset.uiScale;
  app.showStructure = preset.showStructure;
  app.structureDepth = preset.structureDepth;
  app.showPlot = preset.showPlot;
  app.inspector = RayInspector{};
  if (preset.inspectPane >= 0) inspectPixel(app, preset.inspectPane, preset.inspectPixel);
  const bool sameScene = !app.scenePath.empty() && fs::exists(preset.scene) &&
                         fs::exists(app.scenePath) && fs::equivalent(preset.scene, app.scenePath);
  if (preset.camera) {
    app.camera = *preset.camera;
    app.cameraChanged = true;
  }
  if (!sameScene) openScene(app, preset.scene, preset.camera.has_value());
}

bool loadPresetFile(AppState& app, const std::string& path) {
  try {
    applyPreset(app, loadPreset(path));
    addMessage(app, "preset " + path, false);
    return true;
  } catch (const std::exception& e) {
    addMessage(app, e.what());
    return false;
  }
}

ViewPreset capturePreset(const AppState& app) {
  ViewPreset p;
  p.scene = app.scenePath;
  p.camera = app.camera;
  p.width = app.width;
  p.height = app.height;
  p.paneCount = app.paneCount;
  p.compare = app.compare;
  p.exposure = app.exposure;
  p.uiScale = app.uiScale;
  p.showStructure = app.showStructure;
  p.structureDepth = app.structureDepth;
  p.showPlot = app.showPlot;
  p.inspectPane = app.inspector.pane;
  p.inspectPixel = app.inspector.pixel;
  for (const PaneState& pane : app.panes) {
    PaneSetup s;
    s.technique = pane.technique;
    s.accelerator = pane.accelerator;
    s.spp = pane.spp;
    s.view = viewName(pane.view);
    for (const ParamDecl& d : pane.techniqueParams.decls())
      s.techniqueParams[d.name] = pane.techniqueParams.text(d.name);
    for (const ParamDecl& d : pane.accelParams.decls())
      s.accelParams[d.name] = pane.accelParams.text(d.name);
    if (paneSettings(pane) == pane.labelFor) s.label = pane.label;  // (a changed pane lost its label)
    p.panes.push_back(s);
  }
  return p;
}

bool savePresetFile(AppState& app, const std::string& path) {
  try {
    savePreset(capturePreset(app), path);
    addMessage(app, "saved preset " + path, false);
    return true;
  } catch (const std::exception& e) {
    addMessage(app, e.what());
    return false;
  }
}

void resetCamera(AppState& app) {
  if (!app.scene) return;
  app.camera = app.scene->camera;
  app.cameraChanged = true;
}

void frameScene(AppState& app) {
  if (!app.scene) return;
  const Bounds3 b = app.scene->geometry.sceneBounds();
  if (b.empty()) return;
  Camera c = app.camera;
  c.width = renderSettings(app, app.panes[0]).width;
  c.height = renderSettings(app, app.panes[0]).height;
  frameBounds(c, b);
  if (const std::string problem = cameraProblem(c); !problem.empty()) {
    addMessage(app, "Frame scene: the scene's bounds give no usable camera (" + problem + ")");
    return;
  }
  app.camera.eye = c.eye;
  app.camera.target = c.target;
  app.camera.up = c.up;
  app.cameraChanged = true;
}

RenderSettings renderSettings(const AppState& app, const PaneState& pane) {
  RenderSettings s;
  const Camera& sceneCamera = app.scene ? app.scene->camera : app.camera;
  s.width = app.width > 0 ? app.width : sceneCamera.width;
  s.height = app.height > 0 ? app.height : sceneCamera.height;
  if (app.width > 0 && app.height == 0)
    s.height = std::max(1, app.width * sceneCamera.height / sceneCamera.width);
  if (app.height > 0 && app.width == 0)
    s.width = std::max(1, app.height * sceneCamera.width / sceneCamera.height);
  s.spp = pane.spp;
  s.camera = app.camera;
  return s;
}

void submitPanes(AppState& app) {
  if (!app.scene) return;
  // While another scene loads (a preset, a slide, the picker), its settings and camera are not
  // rendered on the scene still shown: the panes stay dirty and start once it has arrived.
  if (!app.loadingPath.empty() && app.loadingPath != app.scenePath) return;
  // Turning the plot on restarts the panes, so that their curves start at their first pass.
  const bool all = app.cameraChanged || (app.showPlot && !app.submittedPlot);
  app.cameraChanged = false;
  app.submittedPlot = app.showPlot;
  for (int i = 0; i < kMaxPanes; ++i) {
    PaneState& pane = app.panes[static_cast<size_t>(i)];
    if (!paneActive(app, i)) {
      if (pane.dirty || all) pane.renderer->stop();
      pane.dirty = true;  // render again when shown
      continue;
    }
    if (!pane.dirty && !all) continue;
    pane.dirty = false;
    if (const std::string problem = cameraProblem(app.camera); !problem.empty()) {
      addMessage(app, "the camera is invalid (" + problem + "); Reset in the Camera section restores the scene's");
      continue;
    }
    RenderRequest r;
    r.scene = app.scene;
    r.sceneVersion = app.sceneVersion;
    r.technique = pane.technique;
    r.accelerator = pane.accelerator;
    r.techniqueParams = pane.techniqueParams;
    r.accelParams = pane.accelParams;
    r.settings = renderSettings(app, pane);
    r.view = pane.view;
    r.keepHistory = app.showPlot;
    pane.submitted = pane.renderer->submit(std::move(r));
  }
}

namespace {
// Appends the phase of the frame about to be drawn to pane.phasesDrawn, when it differs from the last.
void notePhaseDrawn(PaneState& pane) {
  const PaneSnapshot& s = pane.shown;
  if (s.request != pane.phasesRequest) {
    pane.phasesDrawn.clear();
    pane.phasesRequest = s.request;
  }
  if (s.phaseName.empty() || pane.phasesDrawn.size() >= 256) return;
  char fraction[16];
  std::snprintf(fraction, sizeof fraction, "%.1f", s.phaseFraction < 0.0 ? -1.0 : s.phaseFraction);
  std::string entry = s.phaseName + " " + fraction;
  if (pane.phasesDrawn.empty() || pane.phasesDrawn.back() != entry) pane.phasesDrawn.push_back(std::move(entry));
}
}  // namespace

void refreshPanes(AppState& app) {
  for (PaneState& pane : app.panes) {
    pane.shown = pane.renderer->snapshot();
    notePhaseDrawn(pane);
  }
  BackgroundWorker& bg = *app.background;

  // Display bytes of every new image (or after an exposure change).
  for (int i = 0; i < kMaxPanes; ++i) {
    PaneState& pane = app.panes[static_cast<size_t>(i)];
    if (!pane.shown.image ||
        (pane.encodedVersion == pane.shown.version && pane.encodedExposure == app.exposure))
      continue;
    pane.encodedVersion = pane.shown.version;
    pane.encodedExposure = app.exposure;
    bg.post("encode " + std::to_string(i),
            [image = pane.shown.image, mail = pane.display, e = app.exposure,
             cost = isCostView(pane.shown.view), version = pane.shown.version] {
              float scale = 0.0f;
              DisplayImage d = cost ? encodeForDisplay(costHeatmap(*image, 0.0f, &scale), 0.0f)
                                    : encodeForDisplay(*image, e);
              d.legendMax = scale;
              d.version = version;
              mail->put(std::move(d));
            });
  }

  // Errors against the reference pane, on the pictures without stub stripes (PaneSnapshot::measured():
  // a stripe marks where a stub ran, it is not radiance).
  const int ref = app.compare.reference;
  for (int i = 0; i < kMaxPanes; ++i) {
    PaneState& pane = app.panes[static_cast<size_t>(i)];
    if (auto h = pane.historyMail->take()) pane.errorHistory = std::move(*h);
    if (auto e = pane.errorMail->take()) {
      pane.error = e->error;
      pane.hasError = true;
      // Without a kept history (no plot), a point per error measured; a newer reference only
      // refreshes the last point. With one, the curve comes from the history (below).
      if (pane.shown.history.empty()) {
        if (e->request != pane.errorHistoryRequest) pane.errorHistory.clear();
        pane.errorHistoryRequest = e->request;
        if (!pane.errorHistory.empty() && e->seconds <= pane.errorHistory.back().first)
          pane.errorHistory.back().second = e->error.relmse;
        else
          pane.errorHistory.emplace_back(e->seconds, e->error.relmse);
      }
    }
    const PaneSnapshot* refShot = ref >= 0 && ref < kMaxPanes && i != ref
                                      ? &app.panes[static_cast<size_t>(ref)].shown
                                      : nullptr;
    const bool comparable = refShot && pane.shown.image && refShot->image && !pane.shown.preview &&
                            !refShot->preview && pane.shown.view == PaneView::Image &&
                            refShot->view == PaneView::Image &&
                            pane.shown.image->width() == refShot->image->width() &&
                            pane.shown.image->height() == refShot->image->height();
    if (!comparable) {
      pane.hasError = false;
      pane.errorVersions[0] = pane.errorVersions[1] = 0;
      continue;
    }
    // The plot's curve: every kept pass against the reference as it stands now (a newer
    // reference re-measures the whole curve).
    if (!pane.shown.history.empty() &&
        (pane.historyVersions[0] != pane.shown.version || pane.historyVersions[1] != refShot->version)) {
      pane.historyVersions[0] = pane.shown.version;
      pane.historyVersions[1] = refShot->version;
      bg.post("history " + std::to_string(i), [h = pane.shown.history, b = refShot->measured(), mail = pane.historyMail] {
        std::vector<std::pair<double, double>> curve;
        for (const auto& [t, image] : h)
          if (image->width() == b->width() && image->height() == b->height()) curve.emplace_back(t, relativeMse(*image, *b));
        mail->put(std::move(curve));
      });
    }
    if (pane.errorVersions[0] == pane.shown.version && pane.errorVersions[1] == refShot->version)
      continue;
    pane.errorVersions[0] = pane.shown.version;
    pane.errorVersions[1] = refShot->version;
    bg.post("error " + std::to_string(i),
            [a = pane.shown.measured(), b = refShot->measured(), mail = pane.errorMail, t = pane.shown.seconds,
             req = pane.shown.imageRequest] { mail->put({compareImages(*a, *b), t, req}); });
  }

  // The difference heatmap of A against B, without stripes as the errors.
  DiffState& d = app.diff;
  if (app.compare.mode != CompareMode::Difference) return;
  const int a = app.compare.paneA, b = app.compare.paneB;
  const PaneSnapshot& sa = app.panes[static_cast<size_t>(a)].shown;
  const PaneSnapshot& sb = app.panes[static_cast<size_t>(b)].shown;
  if (!sa.image || !sb.image || sa.image->width() != sb.image->width() ||
      sa.image->height() != sb.image->height())
    return;
  if (d.panes[0] == a && d.panes[1] == b && d.versions[0] == sa.version &&
      d.versions[1] == sb.version && d.mode == app.compare.diff &&
      d.requestedMax == app.compare.diffMax)
    return;
  d.panes[0] = a;
  d.panes[1] = b;
  d.versions[0] = sa.version;
  d.versions[1] = sb.version;
  d.mode = app.compare.diff;
  d.requestedMax = app.compare.diffMax;
  bg.post("diff",
          [ia = sa.measured(), ib = sb.measured(), mode = d.mode, max = d.requestedMax, mail = d.mail] {
            DiffState::Result r;
            r.image = encodeForDisplay(differenceHeatmap(*ia, *ib, mode, max, &r.usedMax), 0.0f);
            mail->put(std::move(r));
          });
}

bool paneActive(const AppState& app, int pane) {
  if (pane < app.paneCount || pane == app.compare.reference) return true;
  return app.compare.mode != CompareMode::SideBySide &&
         (pane == app.compare.paneA || pane == app.compare.paneB);
}

bool allPanesFinished(const AppState& app) {
  if (!app.loadingPath.empty()) return false;
  if (!app.scene) return true;  // nothing to render (the scene failed to load)
  for (int i = 0; i < kMaxPanes; ++i) {
    const PaneState& p = app.panes[static_cast<size_t>(i)];
    if (paneActive(app, i) && (p.dirty || !p.renderer->finished())) return false;
  }
  return true;
}

bool stopAllWork(AppState& app, double seconds) {
  for (PaneState& p : app.panes)
    if (p.renderer) p.renderer->stop();
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  const auto ready = [](const std::future<std::shared_ptr<const Scene>>& f) {
    return !f.valid() || f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
  };
  for (;;) {
    bool stopped = ready(app.loading) && std::all_of(app.abandonedLoads.begin(), app.abandonedLoads.end(), ready);
    for (const PaneState& p : app.panes) stopped = stopped && (!p.renderer || p.renderer->finished());
    if (stopped) return true;
    if (Clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

std::vector<std::string> findSceneFiles(const std::vector<std::string>& folders) {
  std::vector<std::string> files;
  for (const std::string& folder : folders) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
      const fs::path p = entry.path();
      if (!entry.is_regular_file() || (p.extension() != ".json" && p.extension() != ".obj"))
        continue;
      if (p.filename() == "scene.schema.json" || isPresetFile(p.string())) continue;
      files.push_back(p.lexically_normal().string());
    }
  }
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());
  return files;
}

}  // namespace ll::gui
