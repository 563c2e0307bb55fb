#include "gui/legend_labels.h"

#include <cstdio>

namespace ll::gui {

namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

std::vector<LegendLabel> legendLabels(float width, float maxValue, bool automatic, float gap, const TextWidth& measure) {
  const LegendLabel zero{"0", 0.0f};
  const float zeroEnd = measure(zero.text) + gap;
  // The top value, with its note where the bar is wide enough for both ends.
  std::string top = number(static_cast<double>(maxValue));
  if (automatic && zeroEnd + measure(top + " (auto, 99th pct)") <= width) top += " (auto, 99th pct)";
  const LegendLabel right{top, width - measure(top)};
  std::vector<LegendLabel> labels{zero};
  const std::string half = number(static_cast<double>(maxValue) / 2);
  const float halfWidth = measure(half), halfX = (width - halfWidth) / 2;
  if (halfX >= zeroEnd && halfX + halfWidth + gap <= right.x) labels.push_back({half, halfX});
  if (right.x >= zeroEnd) labels.push_back(right);  // (else not even the number fits beside "0")
  return labels;
}

}  // namespace ll::gui
