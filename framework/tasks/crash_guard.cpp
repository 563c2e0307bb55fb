#include "tasks/crash_guard.h"

#include "render/student_task.h"
#include "tasks/crash_report.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace ll::tasks {

namespace {

std::atomic<bool> gEnabled{false};
constexpr int kSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL};
constexpr size_t kAltStackBytes = 256 * 1024;

void onFatalSignal(int signal, siginfo_t*, void*) {
  detail::GuardFrame* frame = detail::currentGuard();
  if (!frame) {  // not in student code: die as the signal says
    std::signal(signal, SIG_DFL);
    return;  // the faulting instruction runs again, now with the default action
  }
  frame->signal = signal;
  siglongjmp(frame->env, 1);
}

}  // namespace

namespace detail {

GuardFrame*& currentGuard() {
  thread_local GuardFrame* frame = nullptr;
  return frame;
}

// This thread's alternate signal stack, switched off and freed when the thread ends.
struct AltStack {
  std::vector<char> bytes;
  AltStack() : bytes(kAltStackBytes) {
    stack_t stack{};
    stack.ss_sp = bytes.data();
    stack.ss_size = bytes.size();
    sigaltstack(&stack, nullptr);
  }
  ~AltStack() {
    stack_t off{};
    off.ss_flags = SS_DISABLE;
    sigaltstack(&off, nullptr);
  }
};

void prepareThread() {
  thread_local AltStack stack;
  (void)stack;
}

std::string signalName(int signal) { return signalMeaning(signal); }

}  // namespace detail

void enableCrashGuard() {
  if (gEnabled.exchange(true)) return;
  struct sigaction action {};
  action.sa_sigaction = onFatalSignal;
  // SA_NODEFER: the signal stays unblocked after the jump out of the handler.
  action.sa_flags = SA_SIGINFO | SA_ONSTACK | SA_NODEFER;
  sigemptyset(&action.sa_mask);
  for (int s : kSignals) sigaction(s, &action, nullptr);
}

bool crashGuardEnabled() { return gEnabled.load(std::memory_order_relaxed); }

void noteNaNResult(int task, const char* id, const char* function) {
  thread_local uint64_t serial = 0;
  thread_local std::array<int, 64> counts{};
  const TaskLog* log = currentTaskLog();
  const uint64_t now = log ? log->serial() : 0;
  if (now != serial) {
    serial = now;
    counts.fill(0);
  }
  if (task < 0 || task >= static_cast<int>(counts.size()) || ++counts[static_cast<size_t>(task)] < kNaNStorm) return;
  counts[static_cast<size_t>(task)] = 0;
  throw StudentCrash(std::string(id) + ": your " + function + " keeps returning NaN (" + std::to_string(kNaNStorm) +
                     " times here: a 0/0, or the sqrt or acos of a value out of range?); this render stopped. "
                     "Fix it and save, or tick " + id + " to see its reference.");
}

}  // namespace ll::tasks
