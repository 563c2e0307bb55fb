// Everything the GUI knows, in one explicit struct: the scene, the shared
// camera, the panes and their renderers, the compare mode and the messages.
// The main loop (gui_app.cpp) owns one AppState; the panels read and edit it;
// app_actions.h holds the operations that change it.
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/params.h"
#include "gui/background_worker.h"
#include "gui/display_image.h"
#include "gui/gl_texture.h"
#include "gui/hot_reload.h"
#include "gui/pane_renderer.h"
#include "gui/presenter.h"
#include "gui/ray_inspector.h"
#include "preset/view_preset.h"
#include "metrics/image_metrics.h"
#include "scene/scene.h"

namespace ll::gui {

struct PaneState {
  std::string technique = "raycast";
  std::string accelerator = "none";
  ParamSet techniqueParams,
      accelParams;  // live values; their declarations come from the registries
  // The values of the other techniques and accelerators this pane showed: switching back restores them.
  std::map<std::string, ParamSet> savedTechniqueParams, savedAccelParams;
  int spp = 16;
  PaneView view = PaneView::Image;
  // The preset's name for the pane and the settings it was given for (paneSettings): projector mode
  // shows it while the pane keeps those settings; any change brings back the computed label.
  std::string label, labelFor;
  std::unique_ptr<PaneRenderer> renderer = std::make_unique<PaneRenderer>();
  bool dirty = true;  // settings changed since the last submit
  uint64_t submitted = 0;  // the renderer's id of the last submit (shown.request lags it until the worker starts)
  bool bannerOpen = false;  // the student-task banner under the picture, unfolded (one line per task)

  PaneSnapshot shown;  // copied from the renderer once per UI frame
  // The phases the frames drew for shown.request, in order, as "<phase name> <fraction to 0.1>" (-1.0:
  // unknown; at most 256): a phase shorter than a screenshot's round trip still shows in a test's report.
  std::vector<std::string> phasesDrawn;
  uint64_t phasesRequest = 0;
  GlTexture texture;
  // The sRGB bytes of `shown.image`, encoded on the background worker.
  std::shared_ptr<Mailbox<DisplayImage>> display = std::make_shared<Mailbox<DisplayImage>>();
  uint64_t encodedVersion = 0;
  float encodedExposure = 0.0f;
  // Error against the reference pane, recomputed (in the background) when either image changes.
  bool hasError = false;
  ImageError error;
  struct ErrorSample {
    ImageError error;
    double seconds = 0.0;  // the pane's render time when its image was taken
    uint64_t request = 0;  // the pane's request the image belongs to
  };
  std::shared_ptr<Mailbox<ErrorSample>> errorMail = std::make_shared<Mailbox<ErrorSample>>();
  // Error against the reference over the current request's passes: (wall seconds, relMSE), for the live plot.
  std::vector<std::pair<double, double>> errorHistory;
  uint64_t errorHistoryRequest = 0;
  // With the plot shown: the whole curve, recomputed from the renderer's history
  // (PaneSnapshot::history) whenever it or the reference grows.
  std::shared_ptr<Mailbox<std::vector<std::pair<double, double>>>> historyMail =
      std::make_shared<Mailbox<std::vector<std::pair<double, double>>>>();
  uint64_t historyVersions[2] = {0, 0};
  uint64_t errorVersions[2] = {0, 0};
  // The structure overlay: nodes of the pane's accelerator at the chosen depth (cached).
  std::shared_ptr<const Accelerator> overlayAccel;
  int overlayDepth = -1;
  std::vector<NodeShape> overlayNodes;
};

struct DiffState {  // the difference heatmap of pane A against pane B
  struct Result {
    DisplayImage image;
    float usedMax = 0.0f;
  };
  GlTexture texture;
  std::shared_ptr<Mailbox<Result>> mail = std::make_shared<Mailbox<Result>>();
  // The inputs of the last heatmap requested, to request a new one only on change.
  uint64_t versions[2] = {0, 0};
  int panes[2] = {-1, -1};
  DiffMode mode = DiffMode::Absolute;
  float requestedMax = -1.0f;
  float usedMax = 0.0f;  // scale of the heatmap on screen
  bool valid = false;    // a heatmap is on screen
};

struct Message {
  std::string text;
  bool error = true;
  std::chrono::steady_clock::time_point when;
};

// How long the UI thread worked per frame (not counting the wait for events):
// the proof that no frame waits on a render.
// The first frame (font atlas, first layout) is kept apart as start-up.
struct FrameTimes {
  int frames = 0;
  double firstSeconds = 0.0, sumSeconds = 0.0, maxSeconds = 0.0;
  void add(double seconds) {
    if (++frames == 1) {
      firstSeconds = seconds;
      return;
    }
    sumSeconds += seconds;
    maxSeconds = std::max(maxSeconds, seconds);
  }
};

struct AppState {
  // --- scene -----------------------------------------------------------------
  std::string scenePath;
  std::shared_ptr<const Scene> scene;  // null until the first scene loads
  uint64_t sceneVersion = 0;
  std::filesystem::file_time_type sceneWriteTime{};    // of the file as the shown scene was read
  std::filesystem::file_time_type loadingWriteTime{};  // of the file being loaded, taken before reading it
  bool sceneFileMissing = false;                       // the watched file is gone (said once)
  std::string cameraRefused;  // why the last typed camera value was not applied ("" = it was)
  bool autoReload = true;
  std::chrono::steady_clock::time_point lastWatch;  // when the scene file's time was last checked
  std::string loadingPath;                          // non-empty while a load runs
  std::future<std::shared_ptr<const Scene>> loading;
  // Loads replaced by a newer open, kept until done: destroying a std::async
  // future waits for its task, which would stall the UI.
  std::vector<std::future<std::shared_ptr<const Scene>>> abandonedLoads;
  bool loadKeepsCamera = false;         // a reload keeps the view; opening a new scene resets it
  std::vector<std::string> sceneFiles;   // the file list of the "open" menu
  std::vector<std::string> presetFiles;  // and of the preset picker
  std::string sceneSearch, presetSearch;  // the pickers' search fields
  char pathInput[512] = {};

  // --- the student tree --------------------------------------------------------
  std::string assignment;            // in focus ("A2"; empty = all): banners and captions list its tasks
  std::vector<int> focusReferences;  // tasks the focus switched to their reference (restored on a new focus)
  HotReloadState hotReload;          // --watch: rebuild and reload the student's code on save

  // --- view ------------------------------------------------------------------
  Camera camera;  // shared by every pane
  bool cameraChanged = false;
  int width = 0, height = 0;  // render size in pixels (0 = the scene camera's)
  int paneCount = 2;
  std::array<PaneState, kMaxPanes> panes;
  CompareSetup compare;
  DiffState diff;
  float exposure = 0.0f;       // display exposure, stops
  bool showStructure = false;  // draw the accelerator's nodes over each pane
  int structureDepth = 3;      // at this depth (root = 0)
  RayInspector inspector;      // the ray tree of a clicked pixel
  PresenterState presenter;    // --slides: the deck and the slide on screen
  float uiScale = 1.0f;        // user's scale, times the monitor's content scale
  float contentScale = 1.0f;
  float appliedFontScale = 0.0f;  // the scale the fonts were built at (0: not yet); sizes use uiPx() (ui_scale.h)
  FrameTimes uiFrameWork;
  bool fullscreen = false;
  bool toggleFullscreenRequest = false;  // set by the F11 key callback
  int windowedPos[2] = {100, 100}, windowedSize[2] = {1280, 800};
  bool draggingWipe = false;
  bool draggingView = false;  // a mouse drag that started over the image area
  int settledFrames = 0;      // --screenshot: frames drawn since every pane finished
  uint64_t settledPosts = 0;  // --screenshot: background jobs posted when that count last grew

  // --- the lecture hall ----------------------------------------------------------
  bool projector = false;    // P: one large one-line label per pane naming what differs; stats on I
  bool showStats = false;    // I: in projector mode, each pane's full caption (passes, time, error)
  bool panelHidden = false;  // H: no side panel (or slide text); the panes take the window
  std::chrono::steady_clock::time_point panelHiddenAt;  // for the hint that brings it back
  bool showPlot = false;     // the cost-of-accuracy plot beside the panes
  bool submittedPlot = false;  // showPlot as of the last submit (turning it on restarts the panes)
  std::string plotPngRequest;                  // non-empty: save the plot's pixels there after the next frame
  std::array<float, 4> plotRect{};             // where the plot was drawn last frame (w = 0: hidden)
  std::vector<std::string> paneLabels;         // the projector labels drawn last frame, per visible pane
  std::vector<std::array<float, 4>> labelRects;  // and their boxes
  ImFont* largeFont = nullptr;                 // projector labels (owned by ImGui's font atlas)

  // --- files and messages ------------------------------------------------------
  char presetInput[512] = "preset.json";
  std::vector<std::string> droppedFiles;  // filled by the GLFW drop callback
  std::vector<Message> messages;          // newest last
  std::string screenshotRequest;          // non-empty: save the next frame there
  // Where each pane's image was drawn last frame (window pixels, top-left
  // origin), for the screenshot sidecar: x, y, w, h per pane; w = 0 if hidden.
  std::array<std::array<float, 4>, kMaxPanes> paneRects{};
  std::array<float, 4> compareRect{};
  std::vector<std::array<float, 4>> overlayRects;  // captions and banners drawn over the images
  std::map<std::string, std::array<float, 4>>
      widgetRects;  // named controls the panel drew last frame, for scripted UI tests

  // Last member: destroyed (joined) first, before anything its jobs use.
  std::unique_ptr<BackgroundWorker> background = std::make_unique<BackgroundWorker>();
};

}  // namespace ll::gui
