// The command line's word on a crash in student code. Without it, a segfault
// in a student's function ended `lightlab render` with the shell's bare
// "Segmentation fault" (the GUI names the task: crash_guard.h). Once
// installed, a fatal signal (SIGSEGV, SIGBUS, SIGFPE, SIGILL) raised while a
// task's student code runs on that thread (tasks::StudentCall) prints one
// line naming the task, its file and what the signal usually means; then the
// process dies of the same signal as before, so the grader, which runs
// renders as child processes, still sees the signal, now with a line to show.
// Nothing changes for a crash outside student code, or on a stack overflow in
// a thread without an alternate signal stack.
#pragma once

#include "tasks/visibility.h"

namespace ll::tasks {

// Installs the handlers (idempotent). crash_guard.h's handlers, installed after, take over.
LIGHTLAB_FRAMEWORK_ONLY void installCrashReport();

// What a fatal signal in student code usually means, for the student ("segmentation fault: a bad
// pointer or index, or endless recursion"); a static string (async-signal-safe).
LIGHTLAB_FRAMEWORK_ONLY const char* signalMeaning(int signal);

}  // namespace ll::tasks
