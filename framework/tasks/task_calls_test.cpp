// What a student call records while it runs: its own stub, not another task's report.
#include "tasks/task_calls.h"

#include <gtest/gtest.h>

#include <csignal>

#include "render/student_task.h"
#include "tasks/crash_report.h"
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

// A crash in a task's student code, on the command line: one line naming the task and its file, then
// the process dies of the same signal (the grader's child processes report the signal, now with that
// line); a crash outside student code says nothing more than before.
TEST(CrashReportDeathTest, ACrashInStudentCodeNamesTheTaskAndStillDiesOfTheSignal) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        installCrashReport();
        StudentCall depth(requireTask("A1.3"));
        std::raise(SIGSEGV);
      },
      testing::KilledBySignal(SIGSEGV),
      "lightlab: error: A1.3: your code in assignments/a1_rasterizer/.*\\.cpp crashed \\(segmentation fault");
  EXPECT_EXIT(
      {
        installCrashReport();
        std::raise(SIGFPE);
      },
      testing::KilledBySignal(SIGFPE), "^$");
}

}  // namespace
}  // namespace ll::tasks
