// The labels under a heatmap's colour bar: "0" at its left end, the middle
// value, and the top value at its right end ("41.5 (auto, 99th pct)" when the
// scale follows the image). At a projector's UI scale a pane is narrow for its
// type: labels that would overlap are left out (the middle first, then the
// note after the top value), never drawn over each other.
// Pure (no ImGui): the caller passes how wide a piece of text is drawn.
#pragma once

#include <string>
#include <vector>

#include "gui/caption_wrap.h"

namespace ll::gui {

struct LegendLabel {
  std::string text;
  float x = 0.0f;  // left edge, from the bar's left end (the caller's units: pixels)
};

// Labels for a bar `width` wide scaled 0..maxValue, at least `gap` apart, left to right.
std::vector<LegendLabel> legendLabels(float width, float maxValue, bool automatic, float gap, const TextWidth& measure);

}  // namespace ll::gui
