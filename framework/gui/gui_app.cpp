// The main loop, in the canonical Dear ImGui order: poll events, start the
// frame, build the UI, render, swap. Rendering itself happens on the pane
// workers; this loop only copies their latest images.
#include "gui/gui_app.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <optional>
#include <string>

#include <GL/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include "backends/imgui_impl_glfw.h"
#include "backends/imgui_impl_opengl3.h"

#include "core/error.h"
#include "core/files.h"
#include "gpu/offscreen_gl.h"
#include "gui/app_actions.h"
#include "gui/assignment_focus.h"
#include "gui/file_picker.h"
#include "gui/hot_reload.h"
#include "gui/presenter.h"
#include "gui/screenshot.h"
#include "gui/side_panel.h"
#include "gui/slide_panel.h"
#include "gui/ui_scale.h"
#include "gui/viewport.h"
#include "tasks/crash_guard.h"
#include "tasks/task_modes.h"

namespace ll::gui {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFontPath =
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";  // Debian fonts-dejavu-core
constexpr float kBaseFontPixels = 15.0f;
constexpr float kPanelWidth = 400.0f;  // at UI scale 1
constexpr float kSlidePanelFraction = 0.42f;  // of the window's width, in presenter mode
constexpr float kLabelFontScale = 1.25f;      // projector labels, times the UI font

// GLFW's last error, folded into our one-line messages instead of printed.
std::string gLastGlfwError;
void onGlfwError(int code, const char* text) {
  gLastGlfwError = "GLFW error " + std::to_string(code) + ": " + text;
}

void onDrop(GLFWwindow* window, int count, const char** paths) {
  auto* app = static_cast<AppState*>(glfwGetWindowUserPointer(window));
  for (int i = 0; i < count; ++i) app->droppedFiles.emplace_back(paths[i]);
}

// lightlab_YYYYMMDD_HHMMSS.png in the working directory, or _2, _3... if taken.
std::string timestampedName() {
  const std::time_t now = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "lightlab_%Y%m%d_%H%M%S", std::localtime(&now));
  std::string name = std::string(buf) + ".png";
  for (int n = 2; fs::exists(name); ++n) name = std::string(buf) + "_" + std::to_string(n) + ".png";
  return name;
}

// F11 and F12 act on the key event itself: a press and release that arrive
// within one frame (a quick tap, or xdotool) would be missed by polling.
void onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
  (void)scancode;
  auto* app = static_cast<AppState*>(glfwGetWindowUserPointer(window));
  if (!app || action != GLFW_PRESS) return;
  if (key == GLFW_KEY_F11) app->toggleFullscreenRequest = true;
  if (key == GLFW_KEY_F12) app->screenshotRequest = timestampedName();
  if (key == GLFW_KEY_Q && (mods & GLFW_MOD_CONTROL) != 0) glfwSetWindowShouldClose(window, GLFW_TRUE);
  if (ImGui::GetIO().WantTextInput) return;
  if (handleSlideKey(*app, key)) return;  // presenter mode only
  // The lecture hall: projector labels, stats on demand, the side panel out of the way.
  if (key == GLFW_KEY_P) app->projector = !app->projector;
  if (key == GLFW_KEY_I) app->showStats = !app->showStats;
  if (key == GLFW_KEY_H) {
    app->panelHidden = !app->panelHidden;
    app->panelHiddenAt = std::chrono::steady_clock::now();
  }
}

// Rebuilds the font atlas when the effective scale changed (between frames).
void applyUiScale(AppState& app) {
  const float scale = std::clamp(app.uiScale, 0.5f, 4.0f) * app.contentScale;
  if (std::abs(scale - app.appliedFontScale) < 1e-3f) return;
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  if (fs::exists(kFontPath)) {
    // Presenter mode: Greek and math glyphs for the slides' equations, and the slide fonts.
    const bool slides = app.presenter.active();
    io.Fonts->AddFontFromFileTTF(kFontPath, std::round(kBaseFontPixels * scale), nullptr,
                                 slides ? slideGlyphRanges() : nullptr);
    if (slides) addSlideFonts(app, std::round(kBaseFontPixels * scale));
    app.largeFont = io.Fonts->AddFontFromFileTTF(kFontPath, std::round(kBaseFontPixels * scale * kLabelFontScale));
  } else {
    ImFontConfig config;
    config.SizePixels = std::round(13.0f * scale);
    io.Fonts->AddFontDefault(&config);
    app.largeFont = nullptr;  // labels scale the default font up
  }
  io.Fonts->Build();
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
  ImGuiStyle style;
  ImGui::StyleColorsDark(&style);
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
  app.appliedFontScale = scale;
  setUiScale(scale);
}

// One frame of work that is not drawing: files, scene loads, pane renderers.
void updateApp(AppState& app) {
  for (const std::string& path : app.droppedFiles) openDroppedFile(app, path);
  app.droppedFiles.clear();
  takeSlideRequest(app);
  pollSceneLoad(app);
  watchSceneFile(app);
  updateHotReload(app);
  submitPanes(app);
  refreshPanes(app);
  refreshRayTree(app);
}

void takeScreenshot(AppState& app, GLFWwindow* window, const std::string& path) {
  int fbW = 0, fbH = 0, winW = 0, winH = 0;
  glfwGetFramebufferSize(window, &fbW, &fbH);
  glfwGetWindowSize(window, &winW, &winH);
  try {
    saveFramebufferPng(path, fbW, fbH);
    saveScreenshotSidecar(app, path, fbW, fbH, winW > 0 ? static_cast<float>(fbW) / winW : 1.0f);
    addMessage(app, "screenshot " + path, false);
    std::printf("%s\n", path.c_str());
    std::fflush(stdout);
  } catch (const UserError& e) {
    addMessage(app, e.what());
  }
}

// The plot's pixels as drawn this frame (the side panel's "save PNG").
void savePlotPng(AppState& app, GLFWwindow* window, const std::string& path) {
  int fbW = 0, fbH = 0, winW = 0, winH = 0;
  glfwGetFramebufferSize(window, &fbW, &fbH);
  glfwGetWindowSize(window, &winW, &winH);
  const float k = winW > 0 ? static_cast<float>(fbW) / winW : 1.0f;
  const auto& r = app.plotRect;
  try {
    saveFramebufferRegionPng(path, fbH, static_cast<int>(r[0] * k), static_cast<int>(r[1] * k),
                             static_cast<int>(r[2] * k), static_cast<int>(r[3] * k));
    addMessage(app, "plot " + path, false);
  } catch (const UserError& e) {
    addMessage(app, e.what());
  }
}

}  // namespace

std::vector<std::string> defaultSceneFolders() {
  std::vector<std::string> folders{"data/scenes", "build/data/scenes"};
#ifdef LIGHTLAB_SOURCE_DATA_DIR
  folders.push_back(LIGHTLAB_SOURCE_DATA_DIR "/scenes");
#endif
#ifdef LIGHTLAB_BUILD_DATA_DIR
  folders.push_back(LIGHTLAB_BUILD_DATA_DIR "/scenes");
#endif
  return folders;
}

std::vector<std::string> defaultPresetFolders() {
  std::vector<std::string> folders{"data/presets"};
#ifdef LIGHTLAB_SOURCE_DATA_DIR
  folders.push_back(LIGHTLAB_SOURCE_DATA_DIR "/presets");
#endif
  return folders;
}

std::string defaultScenePath() {
  for (const std::string& folder : defaultSceneFolders()) {
    const fs::path p = fs::path(folder) / "cornell_box.json";
    if (fs::exists(p)) return p.lexically_normal().string();
  }
  throwUserError(
      "cannot find the default scene data/scenes/cornell_box.json; name a scene: lightlab gui "
      "SCENE");
}

int runGui(const GuiOptions& options) {
  // Validate the named files before opening a window, so a typo fails fast.
  std::optional<ViewPreset> preset;
  if (!options.preset.empty()) preset = loadPreset(options.preset);
  std::optional<Deck> deck;
  if (!options.slides.empty()) deck = loadDeck(options.slides);
  if (!options.scene.empty()) checkInputFile(options.scene, "scene file", kMaxMeshFileBytes);
  if (!options.assignment.empty())
    if (const std::string problem = assignmentProblem(options.assignment); !problem.empty())
      throwUserError("--assignment: " + problem);

  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit())
    throwUserError("cannot open a window (" + gLastGlfwError +
                   "); without a display use `lightlab render`");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  GLFWwindow* window =
      glfwCreateWindow(options.windowWidth, options.windowHeight, "LightLab", nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    throwUserError("cannot create an OpenGL 3.3 core window (" + gLastGlfwError +
                   "); without one use `lightlab render`");
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename =
      nullptr;                        // the layout is fixed; presets hold the state worth keeping
  glfwSetKeyCallback(window, onKey);  // before ImGui's backend, which chains to it
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330");
  ImGui_ImplOpenGL3_CreateDeviceObjects();  // before applyUiScale replaces the font texture
  std::string gpuWhy;
  const bool gpu = gpu::OffscreenGl::create(&gpuWhy);  // for GPU techniques on the pane workers

  int exitStatus = 0;
  {
    AppState app;
    app.sceneFiles =
        findSceneFiles(options.sceneFolders.empty() ? defaultSceneFolders() : options.sceneFolders);
    app.presetFiles = findPresetFiles(defaultPresetFolders());
    initPanes(app);
    if (!gpu) addMessage(app, "GPU techniques unavailable: " + gpuWhy);
    glfwSetWindowUserPointer(window, &app);
    glfwSetDropCallback(window, onDrop);
    float xs = 1.0f, ys = 1.0f;
    glfwGetWindowContentScale(window, &xs, &ys);
    app.contentScale = std::max(xs, ys);

    if (preset) applyPreset(app, *preset);
    if (deck) {
      app.uiScale = kPresenterUiScale;
      openDeck(app, std::move(*deck), options.slide - 1);
    }
    // Projector labels: on in presenter mode unless --no-projector; --projector anywhere.
    app.projector = options.projector == 1 || (options.projector == -1 && app.presenter.active());
    if (options.plot) app.showPlot = true;
    startHotReload(app, options.watch != 0);
    if (tasks::modulesEnabled()) tasks::enableCrashGuard();  // a crash in student code stops its pane only
    if (options.watch == 1 && app.hotReload.phase == HotReloadState::Phase::Off)
      addMessage(app, "--watch reloads task modules, which only the student tree builds (LIGHTLAB_SOLUTION=OFF)");
    // The assignment's preset, unless a preset or scene was named (then only the focus).
    const bool assignmentPreset = !options.assignment.empty() && !preset && options.scene.empty() && !deck;
    if (!options.assignment.empty()) focusAssignment(app, options.assignment, assignmentPreset);
    if (!options.scene.empty())
      openScene(app, options.scene, preset && preset->camera);
    else if (!preset && app.presenter.applied < 0 && !assignmentPreset)
      openScene(app, defaultScenePath());
    if (options.uiScale > 0.0f) app.uiScale = options.uiScale;
    std::snprintf(app.pathInput, sizeof app.pathInput, "%s", options.scene.c_str());

    const bool screenshotMode = !options.screenshot.empty();
    if (screenshotMode) waitForSceneLoad(app);
    const auto started = std::chrono::steady_clock::now();
    int frame = 0;
    while (!glfwWindowShouldClose(window)) {
      // 1. Events. Waiting (at most 1/30 s) instead of spinning leaves the cores to the renderers.
      glfwWaitEventsTimeout(1.0 / 30.0);
      const auto frameStart = std::chrono::steady_clock::now();
      applyUiScale(app);
      updateApp(app);

      // 2. New frame.
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();

      // 3. The UI: side panel, image area, input, keys.
      const ImGuiIO& io = ImGui::GetIO();
      const bool slide = app.presenter.active() && !app.presenter.showControls;
      const float panelW = app.panelHidden ? 0.0f
                           : slide         ? io.DisplaySize.x * kSlidePanelFraction
                                           : std::min(uiPx(kPanelWidth), io.DisplaySize.x * 0.5f);
      if (app.panelHidden)
        app.widgetRects.clear();  // no panel drawn: no controls to find
      else if (slide)
        drawSlidePanel(app, 0.0f, 0.0f, panelW, io.DisplaySize.y);
      else
        drawSidePanel(app, window, panelW, io.DisplaySize.y);
      const float vx = panelW, vw = std::max(io.DisplaySize.x - panelW, 1.0f);
      drawViewport(app, vx, 0.0f, vw, io.DisplaySize.y);
      handleCameraInput(app, window, vx, 0.0f, vw, io.DisplaySize.y);
      if (app.toggleFullscreenRequest) {
        app.toggleFullscreenRequest = false;
        toggleFullscreen(app, window);
      }

      // 4. Render and present.
      ImGui::Render();
      int fbW = 0, fbH = 0;
      glfwGetFramebufferSize(window, &fbW, &fbH);
      glViewport(0, 0, fbW, fbH);
      glClearColor(0.11f, 0.11f, 0.125f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      ++frame;
      app.uiFrameWork.add(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - frameStart).count());
      if (!app.screenshotRequest.empty()) {
        takeScreenshot(app, window, app.screenshotRequest);
        app.screenshotRequest.clear();
      }
      if (!app.plotPngRequest.empty()) {
        savePlotPng(app, window, app.plotPngRequest);
        app.plotPngRequest.clear();
      }
      if (screenshotMode && frame >= options.frames) {
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        const bool timedOut = elapsed > options.screenshotTimeout;
        // Two frames after everything finished and the last background job (display bytes, the
        // heatmap, errors) was posted and drained, so its result is collected and drawn.
        const bool finished = allPanesFinished(app);
        if (finished)
          app.background->drain();  // display bytes and heatmap ready for the next frames
        const uint64_t posts = app.background->posted();
        app.settledFrames = finished && posts == app.settledPosts ? app.settledFrames + 1 : 0;
        app.settledPosts = posts;
        if (app.settledFrames >= 2 || timedOut) {
          takeScreenshot(app, window, options.screenshot);
          if (timedOut) {
            std::fprintf(stderr,
                         "lightlab: error: screenshot taken after the %.0f s timeout, before every "
                         "pane finished\n",
                         options.screenshotTimeout);
            exitStatus = 1;
          }
          glfwSetWindowShouldClose(window, GLFW_TRUE);
        }
      }
      glfwSwapBuffers(window);
    }
    // Closing ends the process within a second, whatever runs: work that does not stop in 0.8 s
    // (a mesh build on a big scene, a scene load) is left to the operating system.
    if (!stopAllWork(app, 0.8)) {
      glfwHideWindow(window);
      std::fflush(nullptr);
      std::_Exit(exitStatus);
    }
    for (PaneState& p : app.panes)
      p.renderer.reset();  // join workers while the GL context still exists
  }
  gpu::OffscreenGl::destroy();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return exitStatus;
}

}  // namespace ll::gui
