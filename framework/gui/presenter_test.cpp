// Presenter mode without a window: arriving at a slide applies its preset
// (panes, scene, camera) and keeps the presenter's UI scale; steps clamp at
// both ends; a slide without a preset keeps the view.
#include "gui/presenter.h"

#include <gtest/gtest.h>

#include "gui/app_actions.h"
#include "gui/app_state.h"

namespace ll::gui {
namespace {

const std::string kDeck = std::string(LIGHTLAB_DATA_DIR) + "/../tests/gui/presenter_deck.md";

TEST(Presenter, ArrivingAtASlideAppliesItsPreset) {
  AppState app;
  initPanes(app);
  app.uiScale = 2.0f;
  openDeck(app, loadDeck(kDeck));
  waitForSceneLoad(app);
  EXPECT_EQ(app.presenter.index, 0);
  EXPECT_EQ(app.presenter.applied, 0);
  EXPECT_EQ(app.panes[1].techniqueParams.text("light_samples"), "1");
  EXPECT_TRUE(app.scenePath.ends_with("cornell_box.json"));
  EXPECT_EQ(app.uiScale, 2.0f);  // the preset's ui_scale (1) does not shrink the projector's text

  requestStep(app, 1);
  requestStep(app, 1);
  requestStep(app, 1);  // clamped at the last slide
  takeSlideRequest(app);
  waitForSceneLoad(app);
  EXPECT_EQ(app.presenter.index, 2);
  EXPECT_EQ(app.presenter.applied, 0);  // slide 3 has no preset: slide 1's view stays

  goToSlide(app, 1);
  waitForSceneLoad(app);
  EXPECT_EQ(app.presenter.applied, 1);
  EXPECT_EQ(app.panes[1].technique, "whitted");
  EXPECT_TRUE(app.scenePath.ends_with("whitted_1980.json"));
  EXPECT_EQ(app.camera.eye, app.scene->camera.eye);  // no camera in the preset: the scene's

  requestStep(app, -10);
  takeSlideRequest(app);
  EXPECT_EQ(app.presenter.index, 0);
  EXPECT_EQ(app.presenter.applied, 0);
}

// Opened at a slide without a preset (--slide 3), the view is what stepping there from the first
// slide shows: slide 2's, not the default scene's (nor a later slide's).
TEST(Presenter, OpenedAtASlideWithoutAPresetShowsThePresetBeforeIt) {
  AppState app;
  initPanes(app);
  openDeck(app, loadDeck(kDeck), 2);
  waitForSceneLoad(app);
  EXPECT_EQ(app.presenter.index, 2);
  EXPECT_EQ(app.presenter.applied, 1);
  EXPECT_EQ(app.panes[1].technique, "whitted");
  EXPECT_TRUE(app.scenePath.ends_with("whitted_1980.json"));
}

}  // namespace
}  // namespace ll::gui
