#include "gui/accuracy_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <imgui.h>

#include "core/error.h"
#include "core/markup.h"
#include "gui/pane_labels.h"
#include "gui/ui_scale.h"
#include "gui/viewport.h"

namespace ll::gui {

std::array<uint8_t, 3> paneColor(int pane) {
  // Okabe-Ito colours: told apart by colour-blind viewers, and on a washed-out projector.
  static constexpr std::array<std::array<uint8_t, 3>, kMaxPanes> kColors{
      {{230, 159, 0}, {86, 180, 233}, {0, 158, 115}, {204, 121, 167}}};
  return kColors[static_cast<size_t>(std::clamp(pane, 0, kMaxPanes - 1))];
}

AccuracyPlot accuracyPlot(const AppState& app) {
  AccuracyPlot plot;
  plot.reference = app.compare.reference;
  const std::vector<std::string> labels = distinguishingLabels(app);
  const auto labelOf = [&](int i) {
    return i < static_cast<int>(labels.size()) ? labels[static_cast<size_t>(i)]
                                               : std::string(1, paneLetter(i)) + "  " + app.panes[static_cast<size_t>(i)].technique;
  };
  if (plot.reference >= 0) plot.referenceLabel = labelOf(plot.reference);
  bool any = false;
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (int i = 0; i < app.paneCount; ++i) {
    if (i == plot.reference) continue;
    PlotSeries s;
    s.pane = i;
    s.label = labelOf(i);
    s.color = paneColor(i);
    for (const auto& [t, e] : app.panes[static_cast<size_t>(i)].errorHistory)
      if (t > 0.0 && e > 0.0 && std::isfinite(t) && std::isfinite(e)) {
        s.points.emplace_back(t, e);
        const double lx = std::log10(t), ly = std::log10(e);
        lo[0] = std::min(lo[0], lx), hi[0] = std::max(hi[0], lx);
        lo[1] = std::min(lo[1], ly), hi[1] = std::max(hi[1], ly);
        any = true;
      }
    plot.series.push_back(std::move(s));
  }
  if (any) {
    plot.x0 = std::floor(lo[0]), plot.x1 = std::max(std::ceil(hi[0]), plot.x0 + 1.0);
    plot.y0 = std::floor(lo[1]), plot.y1 = std::max(std::ceil(hi[1]), plot.y0 + 1.0);
  }
  return plot;
}

namespace {

std::string secondsTick(int decade) {
  char buf[32];
  if (decade >= 0)
    std::snprintf(buf, sizeof buf, "%.0f s", std::pow(10.0, decade));
  else
    std::snprintf(buf, sizeof buf, "%.*f s", -decade, std::pow(10.0, decade));
  return buf;
}

std::string errorTick(int decade) { return "1e" + std::to_string(decade); }

std::string title(const AccuracyPlot& plot) {
  if (plot.reference < 0) return "Cost of accuracy: choose a reference pane (Compare: error against)";
  return "Error (relMSE) against " + plot.referenceLabel + ",  over wall time";  // (two spaces: wrapped there)
}

}  // namespace

std::string accuracyPlotSvg(const AccuracyPlot& plot, int width, int height) {
  const double left = 80, right = 20, top = 40, bottom = 50;
  const double pw = width - left - right, ph = height - top - bottom;
  const auto px = [&](double t) { return left + (std::log10(t) - plot.x0) / (plot.x1 - plot.x0) * pw; };
  const auto py = [&](double e) { return top + ph - (std::log10(e) - plot.y0) / (plot.y1 - plot.y0) * ph; };
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
    << "\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"14\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << left << "\" y=\"24\" font-size=\"16\">" << escapeMarkup(title(plot)) << "</text>\n";
  for (int d = static_cast<int>(plot.x0); d <= static_cast<int>(plot.x1); ++d) {
    const double x = left + (d - plot.x0) / (plot.x1 - plot.x0) * pw;
    o << "<line x1=\"" << x << "\" y1=\"" << top << "\" x2=\"" << x << "\" y2=\"" << top + ph
      << "\" stroke=\"#ddd\"/><text x=\"" << x << "\" y=\"" << top + ph + 20 << "\" text-anchor=\"middle\">"
      << secondsTick(d) << "</text>\n";
  }
  for (int d = static_cast<int>(plot.y0); d <= static_cast<int>(plot.y1); ++d) {
    const double y = top + ph - (d - plot.y0) / (plot.y1 - plot.y0) * ph;
    o << "<line x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << left + pw << "\" y2=\"" << y
      << "\" stroke=\"#ddd\"/><text x=\"" << left - 8 << "\" y=\"" << y + 5 << "\" text-anchor=\"end\">"
      << errorTick(d) << "</text>\n";
  }
  o << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"#444\"/>\n"
    << "<text x=\"" << left + pw / 2 << "\" y=\"" << height - 8 << "\" text-anchor=\"middle\">wall time (log)</text>\n"
    << "<text transform=\"translate(16," << top + ph / 2 << ") rotate(-90)\" text-anchor=\"middle\">relMSE (log)</text>\n";
  int row = 0;
  for (const PlotSeries& s : plot.series) {
    char color[16];
    std::snprintf(color, sizeof color, "#%02x%02x%02x", s.color[0], s.color[1], s.color[2]);
    if (!s.points.empty()) {
      o << "<polyline fill=\"none\" stroke=\"" << color << "\" stroke-width=\"3\" points=\"";
      for (const auto& [t, e] : s.points) o << px(t) << "," << py(e) << " ";
      o << "\"/>\n";
      for (const auto& [t, e] : s.points)
        o << "<circle cx=\"" << px(t) << "\" cy=\"" << py(e) << "\" r=\"4\" fill=\"" << color << "\"/>\n";
    }
    const double ly = top + 20 + 22 * row++;
    o << "<line x1=\"" << left + pw - 200 << "\" y1=\"" << ly - 5 << "\" x2=\"" << left + pw - 176 << "\" y2=\""
      << ly - 5 << "\" stroke=\"" << color << "\" stroke-width=\"4\"/><text x=\"" << left + pw - 170 << "\" y=\""
      << ly << "\">" << escapeMarkup(s.label) << "</text>\n";
  }
  o << "</svg>\n";
  return o.str();
}

void saveAccuracyPlotSvg(const AccuracyPlot& plot, const std::string& path, int width, int height) {
  std::ofstream out(path);
  if (!out) throwUserError(path + ": cannot write the plot");
  out << accuracyPlotSvg(plot, width, height);
  if (!out) throwUserError(path + ": cannot write the plot");
}

void drawAccuracyPlot(ImDrawList* dl, const AccuracyPlot& plot, float x, float y, float w, float h) {
  const float s = uiScale(), line = ImGui::GetTextLineHeight();
  dl->AddRectFilled(ImVec2(x, y), ImVec2(x + w, y + h), IM_COL32(18, 18, 22, 255));
  float headHeight = 0.0f;
  for (const std::string& l : wrapCaption({title(plot)}, w - 16 * s)) {
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(x + 8 * s, y + 4 * s + headHeight), IM_COL32_WHITE,
                l.c_str(), nullptr, w - 16 * s);
    headHeight += ImGui::CalcTextSize(l.c_str(), nullptr, false, w - 16 * s).y;
  }
  const float left = x + ImGui::CalcTextSize("1e-10").x + 14 * s, right = x + w - 10 * s;
  const float top = y + headHeight + 10 * s;
  const float bottom = y + h - 2 * line - 8 * s;
  if (right - left < 20 || bottom - top < 20) return;
  const auto px = [&](double lx) { return left + static_cast<float>((lx - plot.x0) / (plot.x1 - plot.x0)) * (right - left); };
  const auto py = [&](double ly) { return bottom - static_cast<float>((ly - plot.y0) / (plot.y1 - plot.y0)) * (bottom - top); };
  const ImU32 grid = IM_COL32(70, 70, 80, 255), text = IM_COL32(220, 220, 220, 255);
  for (int d = static_cast<int>(plot.x0); d <= static_cast<int>(plot.x1); ++d) {
    const float gx = px(d);
    dl->AddLine(ImVec2(gx, top), ImVec2(gx, bottom), grid);
    const std::string t = secondsTick(d);
    const float tw = ImGui::CalcTextSize(t.c_str()).x;  // centred under its line, kept inside the plot
    dl->AddText(ImVec2(std::clamp(gx - tw / 2, x + 2 * s, x + w - tw - 2 * s), bottom + 2 * s), text, t.c_str());
  }
  for (int d = static_cast<int>(plot.y0); d <= static_cast<int>(plot.y1); ++d) {
    const float gy = py(d);
    dl->AddLine(ImVec2(left, gy), ImVec2(right, gy), grid);
    const std::string t = errorTick(d);
    dl->AddText(ImVec2(left - ImGui::CalcTextSize(t.c_str()).x - 6 * s, gy - line / 2), text, t.c_str());
  }
  dl->AddRect(ImVec2(left, top), ImVec2(right, bottom), IM_COL32(160, 160, 170, 255));
  const char* axis = "across: wall time, up: relMSE (both log)";
  dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(),
              ImVec2(std::max((left + right - ImGui::CalcTextSize(axis).x) / 2, x + 4 * s), bottom + line + 4 * s), text,
              axis, nullptr, w - 8 * s);
  float legendY = top + 4 * s;
  for (const PlotSeries& series : plot.series) {
    const ImU32 c = IM_COL32(series.color[0], series.color[1], series.color[2], 255);
    for (size_t k = 1; k < series.points.size(); ++k)
      dl->AddLine(ImVec2(px(std::log10(series.points[k - 1].first)), py(std::log10(series.points[k - 1].second))),
                  ImVec2(px(std::log10(series.points[k].first)), py(std::log10(series.points[k].second))), c, 3.0f * s);
    for (const auto& [t, e] : series.points) dl->AddCircleFilled(ImVec2(px(std::log10(t)), py(std::log10(e))), 3.5f * s, c);
    const std::string label = series.label + (series.points.empty() ? "  (waiting)" : "");
    const float lw = ImGui::CalcTextSize(label.c_str()).x;
    const float lx = right - lw - 34 * s;
    dl->AddRectFilled(ImVec2(lx - 4 * s, legendY - 2 * s), ImVec2(right - 4 * s, legendY + line + 2 * s),
                      IM_COL32(18, 18, 22, 220));
    dl->AddLine(ImVec2(lx, legendY + line / 2), ImVec2(lx + 22 * s, legendY + line / 2), c, 4.0f * s);
    dl->AddText(ImVec2(lx + 28 * s, legendY), text, label.c_str());
    legendY += line + 4 * s;
  }
}

}  // namespace ll::gui
