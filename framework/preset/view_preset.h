// The complete view state of the GUI as a JSON file: scene, camera, render
// size, panes (technique, accelerator and their parameters) and compare mode.
// Slides and demos name these files; `lightlab gui --preset FILE` opens one.
// The format is documented in data/presets/README.md.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "metrics/image_metrics.h"
#include "scene/camera.h"

namespace ll {

constexpr int kMaxPanes = 4;

struct PaneSetup {
  std::string technique = "raycast";
  std::string accelerator = "none";
  std::map<std::string, std::string>
      techniqueParams;  // name -> value as written; missing = default
  std::map<std::string, std::string> accelParams;
  int spp = 16;                // passes of progressive refinement (samples per pixel)
  std::string view = "image";  // image | nodes | primitives (the accelerator's cost per pixel) | light-paths
  std::string label;           // projector mode's name for the pane ("K²E", "Gauss-Seidel"); "" = what differs
};

enum class CompareMode { SideBySide, Wipe, Difference };
const char* compareModeName(CompareMode mode);  // "side-by-side", "wipe", "difference"

struct CompareSetup {
  CompareMode mode = CompareMode::SideBySide;
  float wipe = 0.5f;  // split position for wipe, fraction of the width from the left
  int paneA = 0,
      paneB = 1;  // the two panes wipe and difference show (A left / B right; diff of A against B)
  DiffMode diff = DiffMode::Absolute;
  float diffMax = 0.0f;  // heatmap scale; 0 = automatic (99th percentile)
  int reference = -1;    // pane the error figures are measured against; -1 = none
};

struct ViewPreset {
  std::string description;       // free text: what the view shows (slide figures' captions)
  std::string scene;             // scene path; relative paths resolve against the preset's folder
  std::optional<Camera> camera;  // absent = the scene's own camera
  int width = 0, height = 0;     // render size in pixels; 0 = the scene camera's
  int paneCount = 2;             // 1, 2 or 4 panes shown
  std::vector<PaneSetup> panes;  // kMaxPanes entries after loading (missing ones get defaults)
  CompareSetup compare;
  float uiScale = 1.0f;        // multiplies the monitor's content scale
  float exposure = 0.0f;       // display exposure in stops
  bool showStructure = false;  // the accelerators' nodes drawn over the panes
  int structureDepth = 3;      // at this depth (root = 0)
  int inspectPane = -1;        // the ray tree of this pane's pixel is shown (-1 = none)
  Vec2 inspectPixel{0.0f};     // continuous image position at the render size
  bool showPlot = false;       // the cost-of-accuracy plot (error against compare.reference over time)
};

// Reads a preset, validating every name and value against the registries
// (technique, accelerator, parameter ranges). Throws UserError naming
// file:line:col and the allowed values. Relative scene paths are made
// relative to the current directory (resolved against the preset's folder).
ViewPreset loadPreset(const std::string& path);
// `embedded`: the text is a preset block inside a slide deck, where the
// "lightlab_preset" tag may be left out (the block's fence says what it is).
ViewPreset parsePreset(const std::string& text, const std::string& file,
                       const std::string& baseDir, bool embedded = false);

// Writes `preset` as JSON; the scene path is stored relative to the preset's folder.
void savePreset(const ViewPreset& preset, const std::string& path);
nlohmann::json presetToJson(const ViewPreset& preset, const std::string& baseDir);

}  // namespace ll
