// Focus on an assignment, headless: every assignment's preset loads and sets
// up its panes; an unknown name is a message listing the allowed ones.
#include "gui/assignment_focus.h"

#include <gtest/gtest.h>

#include "gui/app_actions.h"
#include "modules/registry.h"

namespace ll::gui {
namespace {

TEST(AssignmentFocus, EveryAssignmentOpensOnItsPreset) {
  const std::vector<std::string> names = assignmentNames();
  ASSERT_EQ(names, (std::vector<std::string>{"A1", "A2", "A3", "A4", "A5", "A6"}));
  for (const std::string& a : names) {
    SCOPED_TRACE(a);
    AppState app;
    initPanes(app);
    ASSERT_FALSE(assignmentPresetPath(a).empty());
    const bool embree = [] {
      for (const auto& info : accelerators())
        if (info.name == "embree") return true;
      return false;
    }();
    if (a == "A4" && !embree) continue;  // its pane B is Embree, an optional yardstick
    EXPECT_TRUE(focusAssignment(app, a));
    for (const Message& m : app.messages) EXPECT_FALSE(m.error) << m.text;
    EXPECT_EQ(app.assignment, a);
    waitForSceneLoad(app);
    EXPECT_TRUE(app.scene);
    EXPECT_EQ(app.paneCount, 2);
  }
}

TEST(AssignmentFocus, TheA2PaneRunsTheStudentsIntersection) {
  AppState app;
  initPanes(app);
  ASSERT_TRUE(focusAssignment(app, "A2"));
  EXPECT_EQ(app.panes[0].technique, "raycast");
  EXPECT_EQ(app.panes[0].accelerator, "none");
  EXPECT_EQ(app.panes[0].techniqueParams.getChoice("intersection"), "student");
}

TEST(AssignmentFocus, AnUnknownAssignmentIsAMessageNamingTheAllowedOnes) {
  AppState app;
  initPanes(app);
  EXPECT_FALSE(focusAssignment(app, "A9"));
  ASSERT_FALSE(app.messages.empty());
  EXPECT_EQ(app.messages.back().text, "unknown assignment 'A9' (allowed: A1, A2, A3, A4, A5, A6)");
  EXPECT_TRUE(app.assignment.empty());
  EXPECT_TRUE(focusAssignment(app, ""));  // back to every assignment, no preset
}

}  // namespace
}  // namespace ll::gui
