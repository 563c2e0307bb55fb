// A crash in student code stops the work that ran it, not the program (the
// GUI: a segfault in a student's blinnPhong stops that pane with a message
// naming the task). Once enabled, a fatal signal (SIGSEGV, SIGBUS, SIGFPE,
// SIGILL) raised while a guarded call runs on that thread jumps back to the
// call, which throws StudentCrash; raised anywhere else, the signal kills the
// process as usual. A student exception becomes a StudentCrash too, and so
// does a NaN storm: a task function that keeps returning NaN (kNaNStorm times
// on one thread in one render; a single NaN is only a black sample).
//
// Frames skipped by the jump are the student's own (their destructors do not
// run): good enough to keep a window open and say what happened, not to go on
// running that code. The handlers run on an alternate stack, so endless
// recursion is caught as well. The grader does not use this: it runs student
// code in child processes (core/subprocess.h).
#pragma once

#include <csetjmp>
#include <csignal>
#include <exception>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <glm/glm.hpp>

#include "tasks/visibility.h"

namespace ll::tasks {

class StudentCrash : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Installs the handlers (idempotent). Call once, before student code runs.
LIGHTLAB_FRAMEWORK_ONLY void enableCrashGuard();
LIGHTLAB_FRAMEWORK_ONLY bool crashGuardEnabled();

namespace detail {
struct GuardFrame {
  sigjmp_buf env;
  volatile int signal = 0;
  GuardFrame* previous = nullptr;
};
LIGHTLAB_FRAMEWORK_ONLY GuardFrame*& currentGuard();
LIGHTLAB_FRAMEWORK_ONLY void prepareThread();  // the alternate signal stack of this thread
LIGHTLAB_FRAMEWORK_ONLY std::string signalName(int signal);
}  // namespace detail

// Whether a task function's result holds a NaN (float and glm float vectors; other types never).
template <typename T>
bool holdsNaN(const T&) {
  return false;
}
inline bool holdsNaN(float v) { return v != v; }
template <int L, glm::qualifier Q>
bool holdsNaN(const glm::vec<L, float, Q>& v) {
  for (int i = 0; i < L; ++i)
    if (v[i] != v[i]) return true;
  return false;
}

constexpr int kNaNStorm = 16;
// Counts a NaN result of `task`'s student function; throws StudentCrash at the
// kNaNStorm-th on this thread within one render (task log).
LIGHTLAB_FRAMEWORK_ONLY void noteNaNResult(int task, const char* id, const char* function);

// Runs f() (the student's `function` of task `id`) under the guard.
template <typename F>
auto guardedCall(const char* id, const char* function, F&& f) -> decltype(f()) {
  detail::prepareThread();
  detail::GuardFrame frame;
  frame.previous = detail::currentGuard();
  detail::currentGuard() = &frame;
  if (sigsetjmp(frame.env, 0) != 0) {
    detail::currentGuard() = frame.previous;
    throw StudentCrash(std::string(id) + ": your " + function + " crashed (" + detail::signalName(frame.signal) +
                       "); this render stopped. Fix it and save, or tick " + id + " to see its reference.");
  }
  try {
    if constexpr (std::is_void_v<decltype(f())>) {
      f();
      detail::currentGuard() = frame.previous;
    } else {
      auto result = f();
      detail::currentGuard() = frame.previous;
      return result;
    }
  } catch (const StudentCrash&) {
    detail::currentGuard() = frame.previous;
    throw;
  } catch (const std::exception& e) {
    detail::currentGuard() = frame.previous;
    throw StudentCrash(std::string(id) + ": your " + function + " threw an exception: " + e.what());
  } catch (...) {
    detail::currentGuard() = frame.previous;
    throw StudentCrash(std::string(id) + ": your " + function + " threw an exception");
  }
}

}  // namespace ll::tasks
