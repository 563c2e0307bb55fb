// The cost-of-accuracy plot's data and its SVG: one curve per pane but the
// reference, axes in whole decades around every point.
#include "gui/accuracy_plot.h"

#include <gtest/gtest.h>

#include "gui/app_actions.h"

namespace ll::gui {
namespace {

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(AccuracyPlot, OneSeriesPerPaneButTheReferenceWithDecadeAxes) {
  AppState app;
  initPanes(app);
  app.paneCount = 4;
  app.compare.reference = 3;
  for (int i = 0; i < 4; ++i) setTechnique(app, i, "path");
  app.panes[0].spp = 4;
  app.panes[1].spp = 16;
  app.panes[2].spp = 64;
  app.panes[3].spp = 1024;
  app.panes[0].errorHistory = {{0.05, 0.3}, {0.1, 0.15}, {0.2, 0.075}};
  app.panes[1].errorHistory = {{0.5, 0.02}, {2.0, 0.005}};
  const AccuracyPlot plot = accuracyPlot(app);
  ASSERT_EQ(plot.series.size(), 3u);
  EXPECT_EQ(plot.series[0].label, "A  4 spp");
  EXPECT_EQ(plot.referenceLabel, "D  1024 spp");
  EXPECT_EQ(plot.series[2].points.size(), 0u);
  EXPECT_DOUBLE_EQ(plot.x0, -2.0);  // 0.05 s
  EXPECT_DOUBLE_EQ(plot.x1, 1.0);   // 2 s
  EXPECT_DOUBLE_EQ(plot.y0, -3.0);  // 0.005
  EXPECT_DOUBLE_EQ(plot.y1, 0.0);   // 0.3

  const std::string svg = accuracyPlotSvg(plot, 800, 500);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_EQ(count(svg, "<polyline"), 2u);  // C has no points yet
  EXPECT_EQ(count(svg, "<circle"), 5u);
  EXPECT_NE(svg.find("A  4 spp"), std::string::npos);
  EXPECT_NE(svg.find("against D  1024 spp"), std::string::npos);
  EXPECT_NE(svg.find(">0.01 s<"), std::string::npos);
  EXPECT_NE(svg.find(">1e-3<"), std::string::npos);
}

TEST(AccuracyPlot, NoReferenceSaysHowToChooseOne) {
  AppState app;
  initPanes(app);
  app.compare.reference = -1;
  const AccuracyPlot plot = accuracyPlot(app);
  EXPECT_EQ(plot.series.size(), static_cast<size_t>(app.paneCount));
  EXPECT_NE(accuracyPlotSvg(plot, 400, 300).find("choose a reference pane"), std::string::npos);
}

TEST(AccuracyPlot, NonPositiveOrNonFiniteErrorsAreLeftOut) {
  AppState app;
  initPanes(app);
  app.paneCount = 2;
  app.compare.reference = 1;
  app.panes[0].errorHistory = {{0.0, 0.1}, {0.1, 0.0}, {0.2, std::nan("")}, {0.3, 0.01}};
  const AccuracyPlot plot = accuracyPlot(app);
  ASSERT_EQ(plot.series.size(), 1u);
  EXPECT_EQ(plot.series[0].points.size(), 1u);
}

}  // namespace
}  // namespace ll::gui
