// Which code runs for each task, and how a stub that ran is reported: the
// reference answered for it, or, under --isolate, the student's stub itself.
#include "tasks/task_modes.h"

#include <gtest/gtest.h>

#include "tasks/task_catalog.h"

namespace ll::tasks {
namespace {

// Restores every task's mode after a test (the modes are process-wide).
struct ModesRestored {
  ~ModesRestored() { setAllModes(Mode::Auto); }
};

TEST(TaskModes, IsolateRunsOneTaskAsWrittenAndEveryOtherByItsReference) {
  const ModesRestored restore;
  const int owner = requireTask("A6.4");
  isolateTask(owner);
  EXPECT_EQ(mode(owner), Mode::Student);
  EXPECT_EQ(mode(requireTask("A6.2")), Mode::Reference);
  EXPECT_EQ(mode(requireTask("A1.1")), Mode::Reference);
  useReferences("A2.3,A6");
  EXPECT_EQ(mode(requireTask("A2.3")), Mode::Reference);
  EXPECT_EQ(mode(requireTask("A6.4")), Mode::Reference);
  EXPECT_EQ(mode(requireTask("A2.1")), Mode::Auto);
  EXPECT_THROW(useReferences("A9.1"), std::exception);
}

// The message after "A6.4 not implemented: ... --" says what the picture shows.
TEST(TaskModes, AStubsOutcomeSaysWhoseAnswerThePictureShows) {
  const ModesRestored restore;
  EXPECT_EQ(stubOutcome("A6.4", false), "its reference stood in; those pixels are striped magenta");
  EXPECT_EQ(stubOutcome("A4.1", true), "its reference stood in (the same picture)");
  EXPECT_EQ(stubOutcome("A5.1", false, false), "its reference stood in");
  isolateTask(requireTask("A6.4"));  // the stub's own placeholder, not the reference
  EXPECT_EQ(stubOutcome("A6.4", false), "your stub ran (--isolate); those pixels are striped magenta");
  EXPECT_EQ(stubOutcome("A6.2", false), "its reference stood in; those pixels are striped magenta");
}

}  // namespace
}  // namespace ll::tasks
