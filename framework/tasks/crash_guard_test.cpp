#include "tasks/crash_guard.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "render/student_task.h"

namespace ll::tasks {
namespace {

#if defined(__SANITIZE_ADDRESS__)
#define LIGHTLAB_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LIGHTLAB_UNDER_ASAN 1
#endif
#endif

#ifndef LIGHTLAB_UNDER_ASAN  // the signal tests only
volatile int* volatile gNowhere = nullptr;  // volatile: neither the access nor the load can be optimised away
volatile bool gStop = false;

int crashHere(int depth) {
  volatile int* nowhere = gNowhere;
  return depth > 0 ? crashHere(depth - 1) + 1 : *nowhere;
}

int recurseForever(int n) {
  if (gStop) return 0;
  volatile int keep[64];
  keep[0] = n;
  return recurseForever(n + 1) + keep[0];
}
#endif

TEST(CrashGuard, ASegfaultInGuardedCodeThrowsNamingTheTask) {
#ifdef LIGHTLAB_UNDER_ASAN
  GTEST_SKIP() << "AddressSanitizer owns SIGSEGV";
#else
  enableCrashGuard();
  try {
    guardedCall("A2.4", "blinnPhong", [] { return crashHere(3); });
    FAIL() << "no StudentCrash";
  } catch (const StudentCrash& e) {
    EXPECT_NE(std::string(e.what()).find("A2.4: your blinnPhong crashed (segmentation fault"), std::string::npos)
        << e.what();
  }
  // The guard is whole again: a second crash is caught too, and plain calls return.
  EXPECT_THROW(guardedCall("A2.4", "blinnPhong", [] { return crashHere(0); }), StudentCrash);
  EXPECT_EQ(guardedCall("A2.4", "blinnPhong", [] { return 7; }), 7);
#endif
}

TEST(CrashGuard, EndlessRecursionIsCaughtOnTheAlternateStack) {
#ifdef LIGHTLAB_UNDER_ASAN
  GTEST_SKIP() << "AddressSanitizer owns SIGSEGV";
#else
  enableCrashGuard();
  EXPECT_THROW(guardedCall("A3.4", "trace", [] { return recurseForever(0); }), StudentCrash);
#endif
}

TEST(CrashGuard, AStudentExceptionNamesTheTask) {
  try {
    guardedCall("A5.2", "solve", []() -> int { throw std::out_of_range("vector::at"); });
    FAIL() << "no StudentCrash";
  } catch (const StudentCrash& e) {
    EXPECT_STREQ(e.what(), "A5.2: your solve threw an exception: vector::at");
  }
}

TEST(CrashGuard, ANaNStormStopsTheRenderNamingTheTask) {
  EXPECT_TRUE(holdsNaN(std::numeric_limits<float>::quiet_NaN()));
  EXPECT_TRUE(holdsNaN(glm::vec3(0.0f, std::numeric_limits<float>::quiet_NaN(), 1.0f)));
  EXPECT_FALSE(holdsNaN(glm::vec3(std::numeric_limits<float>::infinity())));
  EXPECT_FALSE(holdsNaN(true));
  TaskLog log;
  const ScopedTaskLog scoped(&log);
  for (int i = 1; i < kNaNStorm; ++i) noteNaNResult(3, "A2.4", "blinnPhong");  // a few NaNs: black samples only
  try {
    noteNaNResult(3, "A2.4", "blinnPhong");
    FAIL() << "no StudentCrash";
  } catch (const StudentCrash& e) {
    EXPECT_NE(std::string(e.what()).find("A2.4: your blinnPhong keeps returning NaN"), std::string::npos) << e.what();
  }
  log.clear();  // a new render starts counting again
  EXPECT_NO_THROW(noteNaNResult(3, "A2.4", "blinnPhong"));
}

}  // namespace
}  // namespace ll::tasks
