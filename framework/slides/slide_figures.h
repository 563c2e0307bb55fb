// The figures of a deck: each slide's preset rendered headless
// (renderPresetFigure) and encoded as PNG. Figures render at twice the
// preset's size (its width and height, else its scene camera's) and are shown
// at the preset's size, sharp on high-density screens and projectors;
// --max-width caps the doubled render. A figure that fails records why and
// the others still render, so one build reports every failure.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "preset/preset_render.h"
#include "slides/deck_html.h"

namespace ll {

struct FigureReport {
  int width = 0, height = 0;  // of the PNG (up to twice the figure's size in the page)
  double seconds = 0.0;
  std::map<std::string, std::string> missingTasks;
};

// One entry per slide (empty for slides without a preset). onProgress(figures
// done, fractional) is called after each pass. `reports` (optional) gets one
// entry per slide too.
std::vector<SlideFigure> renderDeckFigures(const Deck& deck, const FigureLimits& limits,
                                           const std::function<void(double)>& onProgress = {},
                                           std::vector<FigureReport>* reports = nullptr);

// The image as an 8-bit sRGB PNG file's bytes.
std::string pngBytes(const Image& image);

}  // namespace ll
