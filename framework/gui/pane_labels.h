// What tells the panes on screen apart, in one short line each: the
// projector label. "A  depth 2" on a slide whose panes differ only in
// Whitted's recursion depth; "B  path  64 spp" when technique and sample
// count differ. Pure (no ImGui), so it is unit-tested headless.
#pragma once

#include <string>
#include <vector>

#include "gui/app_state.h"

namespace ll::gui {

// One label per visible pane (app.paneCount of them), the pane letter first.
// Names the technique, the accelerator, the pane view, the samples per pixel
// and every technique or accelerator parameter whose value is not the same
// in all visible panes (a parameter of a technique only among the panes
// that run it). A single pane, or panes that are all alike, show the technique.
// A pane with a preset's label (and still its settings) shows that label.
std::vector<std::string> distinguishingLabels(const AppState& app);

// Per visible pane, what differs from the other panes besides the technique
// and the accelerator ("depth 2  64 spp"; empty if nothing), for the
// captions that name those two anyway.
std::vector<std::string> parameterDifferences(const AppState& app);

// The settings a pane's picture depends on (technique, accelerator, their
// parameters, samples, view) as one string: a preset's pane label holds while they do.
std::string paneSettings(const PaneState& pane);

// The short name a parameter goes by in a label: "depth" for max_depth,
// else the name with spaces for underscores.
std::string shortParamName(const std::string& name);

}  // namespace ll::gui
