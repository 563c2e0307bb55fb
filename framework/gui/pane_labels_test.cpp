// Projector labels name what differs between the panes, and only that.
#include "gui/pane_labels.h"

#include <gtest/gtest.h>

#include "gui/app_actions.h"
#include "modules/registry.h"

namespace ll::gui {
namespace {

void use(AppState& app, int pane, const std::string& technique, const std::string& accelerator = "bvh") {
  setTechnique(app, pane, technique);
  setAccelerator(app, pane, accelerator);
}

TEST(PaneLabels, RecursionDepthSlideNamesEachPanesDepth) {
  AppState app;
  initPanes(app);
  app.paneCount = 4;
  const char* depths[] = {"0", "1", "2", "5"};
  for (int i = 0; i < 4; ++i) {
    use(app, i, "whitted");
    app.panes[static_cast<size_t>(i)].spp = 4;
    app.panes[static_cast<size_t>(i)].techniqueParams.set("max_depth", depths[i]);
  }
  EXPECT_EQ(distinguishingLabels(app),
            (std::vector<std::string>{"A  depth 0", "B  depth 1", "C  depth 2", "D  depth 5"}));
  EXPECT_EQ(parameterDifferences(app), (std::vector<std::string>{"depth 0", "depth 1", "depth 2", "depth 5"}));
}

TEST(PaneLabels, TechniquesAndSampleCountsThatDifferAreNamed) {
  AppState app;
  initPanes(app);
  app.paneCount = 2;
  use(app, 0, "raycast");
  use(app, 1, "path");
  app.panes[0].spp = 4;
  app.panes[1].spp = 64;
  EXPECT_EQ(distinguishingLabels(app), (std::vector<std::string>{"A  raycast  4 spp", "B  path  64 spp"}));
  // The panes' own parameters say nothing here: neither technique runs in the other pane.
  EXPECT_EQ(parameterDifferences(app), (std::vector<std::string>{"4 spp", "64 spp"}));
}

TEST(PaneLabels, AcceleratorsAreNamedWhenOnlyTheyDiffer) {
  AppState app;
  initPanes(app);
  app.paneCount = 2;
  use(app, 0, "path", "bvh");
  use(app, 1, "path", "kdtree");
  app.panes[0].spp = app.panes[1].spp = 16;
  EXPECT_EQ(distinguishingLabels(app), (std::vector<std::string>{"A  bvh", "B  kdtree"}));
}

// The BSP slide: one accelerator, its picture beside its nodes-visited heatmap. Only B had a
// view to name, so the labels named neither.
TEST(PaneLabels, APictureBesideAHeatmapIsNamed) {
  AppState app;
  initPanes(app);
  app.paneCount = 2;
  use(app, 0, "raycast", "bsp");
  use(app, 1, "raycast", "bsp");
  app.panes[0].spp = app.panes[1].spp = 1;
  app.panes[1].view = PaneView::NodesVisited;
  EXPECT_EQ(distinguishingLabels(app), (std::vector<std::string>{"A  picture", "B  nodes visited"}));
}

// The shading slide: three rasterized panes (no accelerator) beside a ray-cast one. The
// accelerator only follows the technique there: the labels name the shading, not "none".
TEST(PaneLabels, AnAcceleratorThatOnlyFollowsTheTechniqueIsNotNamed) {
  AppState app;
  initPanes(app);
  app.paneCount = 4;
  const char* shading[] = {"flat", "gouraud", "phong"};
  for (int i = 0; i < 3; ++i) {
    use(app, i, "blinn-phong", "none");
    app.panes[static_cast<size_t>(i)].techniqueParams.set("shading", shading[i]);
  }
  use(app, 3, "raycast", "bvh");
  for (PaneState& p : app.panes) p.spp = 4;
  EXPECT_EQ(distinguishingLabels(app), (std::vector<std::string>{"A  blinn-phong  shading flat", "B  blinn-phong  shading gouraud",
                                                                 "C  blinn-phong  shading phong", "D  raycast"}));
  // Brute force by name, where the accelerator is the difference.
  app.paneCount = 2;
  use(app, 0, "raycast", "none");
  use(app, 1, "raycast", "bvh");
  EXPECT_EQ(distinguishingLabels(app), (std::vector<std::string>{"A  brute force", "B  bvh"}));
}

// A preset may name its panes for the slide's concept ("K²E"); the name holds while the pane keeps
// the preset's settings, and any change brings back what differs.
TEST(PaneLabels, APresetsPaneLabelHoldsUntilThePaneChanges) {
  AppState app;
  initPanes(app);
  ViewPreset preset;
  preset.paneCount = 2;
  preset.scene = std::string(LIGHTLAB_DATA_DIR) + "/scenes/cornell_box.json";
  preset.panes.resize(kMaxPanes);
  preset.panes[0] = {"raycast", "bvh", {{"light_samples", "1"}}, {}, 4, "image", "one sample"};
  preset.panes[1] = {"raycast", "bvh", {{"light_samples", "64"}}, {}, 4, "image", ""};
  applyPreset(app, preset);
  waitForSceneLoad(app);
  EXPECT_EQ(distinguishingLabels(app), (std::vector<std::string>{"A  one sample", "B  light samples 64"}));
  app.panes[0].techniqueParams.set("light_samples", "2");
  EXPECT_EQ(distinguishingLabels(app), (std::vector<std::string>{"A  light samples 2", "B  light samples 64"}));
  EXPECT_TRUE(capturePreset(app).panes[0].label.empty());
  app.panes[0].techniqueParams.set("light_samples", "1");  // back to the preset's settings: its name again
  EXPECT_EQ(distinguishingLabels(app)[0], "A  one sample");
  EXPECT_EQ(capturePreset(app).panes[0].label, "one sample");
}

TEST(PaneLabels, OnePaneOrAlikePanesShowTheTechnique) {
  AppState app;
  initPanes(app);
  app.paneCount = 1;
  use(app, 0, "whitted");
  EXPECT_EQ(distinguishingLabels(app), (std::vector<std::string>{"A  whitted"}));
  app.paneCount = 2;
  use(app, 1, "whitted");
  app.panes[1].spp = app.panes[0].spp;
  app.panes[1].techniqueParams = app.panes[0].techniqueParams;
  EXPECT_EQ(distinguishingLabels(app), (std::vector<std::string>{"A  whitted", "B  whitted"}));
}

TEST(PaneLabels, ShortParameterNames) {
  EXPECT_EQ(shortParamName("max_depth"), "depth");
  EXPECT_EQ(shortParamName("patch_size"), "patch size");
}

}  // namespace
}  // namespace ll::gui
