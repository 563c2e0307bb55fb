// `lightlab gui`: the interactive window. One GLFW window with an OpenGL 3.3
// core context and Dear ImGui; the main loop lives in gui_app.cpp.
#pragma once

#include <string>
#include <vector>

namespace ll::gui {

struct GuiOptions {
  std::string scene;   // scene to open; empty = the default Cornell box (unless a preset names one)
  std::string preset;  // view preset to apply first
  std::string slides;  // presenter mode: this Markdown deck beside the panes
  int slide = 1;       // with `slides`: the slide to start at, 1-based
  std::string screenshot;  // non-empty: after `frames` UI frames and every pane finished, save the
                           // window and exit
  int frames = 10;
  double screenshotTimeout =
      900.0;  // seconds; the screenshot is taken anyway after this, and the exit status is 1
  int windowWidth = 1280, windowHeight = 800;
  float uiScale = 0.0f;                   // 0 = keep the preset's (or 1)
  std::vector<std::string> sceneFolders;  // where the "open" list looks for scenes
  std::string assignment;  // "A2": open on its preset, banners name its tasks only (empty = all)
  int watch = -1;          // rebuild and reload the student's code on save: 1 on, 0 off, -1 = on in the student tree
  int projector = -1;      // projector mode: 1 on, 0 off, -1 = on in presenter mode
  bool plot = false;       // the cost-of-accuracy plot beside the panes
};

// Runs until the window closes. Returns the process exit status. Throws
// UserError if no window can be opened (no display) or a named file is bad.
int runGui(const GuiOptions& options);

// The folders with bundled scenes: data/scenes under the working directory
// and under the source tree, and the build's generated scenes.
std::vector<std::string> defaultSceneFolders();
// The folders with bundled presets (data/presets, searched recursively).
std::vector<std::string> defaultPresetFolders();
// The default scene (the Cornell box), found the same way.
std::string defaultScenePath();

}  // namespace ll::gui
