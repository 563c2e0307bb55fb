// What a student call records while it runs: its own stub, not another task's report.
#include "tasks/task_calls.h"

#include <gtest/gtest.h>

#include "render/student_task.h"
#include "tasks/task_catalog.h"

namespace ll::tasks {
namespace {

// The walk of the A3 handout: with the student's A3.4 and A4.1 still a stub, the BVH reports its
// exact fallback on every query, from inside A3.4's call. Counted as A3.4's stub, it made the
// reference re-run every bounce's subtree: 23x the rays at depth 5.
TEST(StudentCall, AnotherTasksStubReportIsNotThisCallsStub) {
  {
    StudentCall whitted(requireTask("A3.4"));
    reportMissingTask("A4.1", "BVH build (a test's report)", false);  // as the BVH does on each query
    EXPECT_FALSE(whitted.stubRan());
    {
      StudentCall traversal(requireTask("A4.2"));  // a task called from inside: its own stub is its own
      reportMissingTask("A4.2", "BVH traversal (a test's report)", false);
      EXPECT_TRUE(traversal.stubRan());
    }
    EXPECT_FALSE(whitted.stubRan());  // and does not leak out of it
    reportMissingTask("A3.4", "Whitted recursion (a test's report)");
    EXPECT_TRUE(whitted.stubRan());
  }
  // What the reports left on this thread and process, cleared for the tests after this one.
  takeStubFlag();
  takeTasksReported();
}

}  // namespace
}  // namespace ll::tasks
