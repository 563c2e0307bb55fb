// A view preset rendered headless: the picture the GUI would show for it,
// made the way `lightlab render` makes one (scene loader, registry
// accelerator, RenderJob with the preset's camera, size, passes and seed 0).
// Slide figures come from here.
#pragma once

#include <functional>
#include <map>
#include <string>

#include "core/image.h"
#include "preset/view_preset.h"

namespace ll {

// Caps for quick builds (CI, drafts); 0 = the preset's own value.
struct FigureLimits {
  int maxWidth = 0;  // pixels per pane; larger presets are scaled down, keeping the aspect ratio
  int maxSpp = 0;    // passes per pane
};

struct PresetFigure {
  Image image;  // display-ready linear RGB (exposure applied; heatmaps as drawn): save as sRGB PNG
  int paneWidth = 0, paneHeight = 0;           // render size of each pane
  std::map<std::string, std::string> missingTasks;  // student task ID -> what, if a stub ran
  double seconds = 0.0;                        // wall time, scene load included
  std::vector<std::string> notes;  // what the picture cannot say: each light-path tile's class and share
};

// The panes the preset's compare mode shows: side by side, 1, 2 or 4 panes
// (4 as a 2x2 grid, 4-pixel gaps); wipe, A left of the split and B right;
// difference, the heatmap of A against B. Panes with view "nodes" or
// "primitives" show the accelerator's cost heatmap, as in the GUI.
// onProgress(fraction done in [0, 1]) is called after each pass.
// GPU techniques need an offscreen GL context first (presetNeedsGpu).
// Throws UserError for a bad scene or parameter.
PresetFigure renderPresetFigure(const ViewPreset& preset, const FigureLimits& limits = {},
                                const std::function<void(double)>& onProgress = {});

// True if a pane the figure shows uses a GPU technique.
bool presetNeedsGpu(const ViewPreset& preset);

}  // namespace ll
