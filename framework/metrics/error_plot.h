// Error against time as a picture: an SVG line plot with logarithmic axes,
// one polyline per series, each point labelled (the knob's value). Used by
// `lightlab study`; the SVG is text, so reports embed it inline.
#pragma once

#include <string>
#include <vector>

namespace ll {

struct PlotPoint {
  double x = 0.0, y = 0.0;  // both > 0 (others are left out)
  std::string label;
};

struct PlotSeries {
  std::string name;
  std::vector<PlotPoint> points;
};

// width x height pixels; axes span whole decades around the data.
std::string logLogSvg(const std::vector<PlotSeries>& series, const std::string& title, const std::string& xLabel,
                      const std::string& yLabel, int width = 640, int height = 420);

}  // namespace ll
