#include "metrics/error_plot.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/markup.h"

namespace ll {

namespace {

constexpr const char* kColours[] = {"#c0392b", "#2459a8", "#2e8540", "#d4a017", "#8e44ad", "#16a085"};

}  // namespace

std::string logLogSvg(const std::vector<PlotSeries>& series, const std::string& title, const std::string& xLabel,
                      const std::string& yLabel, int width, int height) {
  const double w = width, h = height, left = 70, right = 110, top = 40, bottom = 50;
  double xlo = 1e300, xhi = -1e300, ylo = 1e300, yhi = -1e300;
  for (const PlotSeries& s : series)
    for (const PlotPoint& p : s.points) {
      if (!(p.x > 0.0 && p.y > 0.0 && std::isfinite(p.x) && std::isfinite(p.y))) continue;
      xlo = std::min(xlo, std::log10(p.x));
      xhi = std::max(xhi, std::log10(p.x));
      ylo = std::min(ylo, std::log10(p.y));
      yhi = std::max(yhi, std::log10(p.y));
    }
  if (xlo > xhi) xlo = xhi = ylo = yhi = 0.0;  // nothing to draw
  xlo = std::floor(xlo);
  xhi = std::max(std::ceil(xhi), xlo + 1.0);
  ylo = std::floor(ylo);
  yhi = std::max(std::ceil(yhi), ylo + 1.0);
  const auto x = [&](double v) { return left + (w - left - right) * (std::log10(v) - xlo) / (xhi - xlo); };
  const auto y = [&](double v) { return top + (h - top - bottom) * (yhi - std::log10(v)) / (yhi - ylo); };
  std::ostringstream out;
  out << "<svg xmlns='http://www.w3.org/2000/svg' width='" << w << "' height='" << h
      << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n"
      << "<text x='" << left << "' y='24' font-size='14'>" << escapeMarkup(title) << "</text>\n";
  for (double d = xlo; d <= xhi; d += 1.0) {
    const double px = left + (w - left - right) * (d - xlo) / (xhi - xlo);
    out << "<line x1='" << px << "' x2='" << px << "' y1='" << top << "' y2='" << h - bottom
        << "' stroke='#ddd'/><text x='" << px << "' y='" << h - bottom + 16 << "' text-anchor='middle'>1e" << d
        << "</text>\n";
  }
  for (double d = ylo; d <= yhi; d += 1.0) {
    const double py = top + (h - top - bottom) * (yhi - d) / (yhi - ylo);
    out << "<line x1='" << left << "' x2='" << w - right << "' y1='" << py << "' y2='" << py
        << "' stroke='#ddd'/><text x='" << left - 8 << "' y='" << py + 4 << "' text-anchor='end'>1e" << d
        << "</text>\n";
  }
  out << "<text x='" << (left + w - right) / 2 << "' y='" << h - 12 << "' text-anchor='middle'>" << escapeMarkup(xLabel)
      << "</text>\n<text x='16' y='" << (top + h - bottom) / 2 << "' transform='rotate(-90 16 "
      << (top + h - bottom) / 2 << ")' text-anchor='middle'>" << escapeMarkup(yLabel) << "</text>\n";
  for (size_t k = 0; k < series.size(); ++k) {
    const char* colour = kColours[k % (sizeof(kColours) / sizeof(kColours[0]))];
    out << "<polyline fill='none' stroke='" << colour << "' stroke-width='2' points='";
    for (const PlotPoint& p : series[k].points)
      if (p.x > 0.0 && p.y > 0.0) out << x(p.x) << "," << y(p.y) << " ";
    out << "'/>\n";
    for (const PlotPoint& p : series[k].points) {
      if (!(p.x > 0.0 && p.y > 0.0)) continue;
      out << "<circle cx='" << x(p.x) << "' cy='" << y(p.y) << "' r='3' fill='" << colour << "'/><text x='"
          << x(p.x) + 5 << "' y='" << y(p.y) - 5 << "' font-size='10'>" << escapeMarkup(p.label) << "</text>\n";
    }
    out << "<text x='" << w - right + 8 << "' y='" << top + 16 * static_cast<double>(k + 1) << "' fill='" << colour
        << "'>" << escapeMarkup(series[k].name) << "</text>\n";
  }
  out << "</svg>\n";
  return out.str();
}

}  // namespace ll
