// The cost of accuracy, live: every pane's error against the reference pane
// (relMSE, log scale) over its wall time (log scale), one coloured curve per
// pane, a point per pass. Drawn beside the panes (viewport.cpp), exported as
// SVG (written here) or PNG (the plot's pixels, gui_app.cpp). The data part
// is pure, so it is unit-tested headless.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "gui/app_state.h"

struct ImDrawList;

namespace ll::gui {

struct PlotSeries {
  int pane = 0;
  std::string label;                               // the pane's projector label ("A  depth 2")
  std::array<uint8_t, 3> color{};                  // sRGB
  std::vector<std::pair<double, double>> points;   // (seconds > 0, relMSE > 0), time order
};

struct AccuracyPlot {
  int reference = -1;          // pane the errors are measured against (-1: none chosen)
  std::string referenceLabel;  // its label
  std::vector<PlotSeries> series;  // the visible panes but the reference, in pane order
  // Axis ranges in log10 units, whole decades around every point.
  double x0 = -1.0, x1 = 1.0, y0 = -4.0, y1 = 0.0;
};

// The plot of the panes on screen as of now.
AccuracyPlot accuracyPlot(const AppState& app);
// The colour of pane `pane`'s curve (also its label's accent on screen).
std::array<uint8_t, 3> paneColor(int pane);

// A standalone SVG picture of `plot`, width x height pixels.
std::string accuracyPlotSvg(const AccuracyPlot& plot, int width, int height);
// Writes accuracyPlotSvg to `path`; throws UserError when it cannot.
void saveAccuracyPlotSvg(const AccuracyPlot& plot, const std::string& path, int width = 960, int height = 600);

// Draws the plot into `dl` over the rectangle (x, y, w, h), window pixels.
void drawAccuracyPlot(ImDrawList* dl, const AccuracyPlot& plot, float x, float y, float w, float h);

}  // namespace ll::gui
