// How student stubs report themselves. A stub calls
//   LIGHTLAB_TODO("A2.4", "Blinn-Phong shading");
// and returns a placeholder (no working answer: deleting the line does not
// make the task pass). In the student tree the task's reference then stands
// in for that call (tasks/task_modes.h), the render records the task as
// missing (the CLI and GUI name it), and the pixels that went through the
// stub get magenta stripes -- never a crash and never a silently black image.
// Tasks whose reference gives the same picture, only faster (the
// accelerators), use LIGHTLAB_TODO_EXACT: reported, not striped.
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <mutex>
#include <set>
#include <string>

#include "tasks/visibility.h"

namespace ll {

// Missing tasks seen during one render (thread-safe).
class TaskLog {
 public:
  TaskLog();
  // exact: the stub's fallback gives the same result (only slower), no pixel is striped.
  void report(const std::string& id, const std::string& what, bool exact = false);
  std::map<std::string, std::string> missing() const;  // id -> description
  std::set<std::string> exact() const;                 // the missing ids whose fallback is exact
  // A task's code broke a rule (it used the framework's own answer to itself, ...).
  void reportViolation(const std::string& id, const std::string& message);
  std::map<std::string, std::string> violations() const;  // id -> message
  // The tasks this render called, and who answered: false = the student's code
  // (a stub included), true = the reference (tasks/task_modes.h).
  void noteRan(const std::string& id, bool byReference);
  std::map<std::string, bool> ran() const;
  void clear();
  // Unique for this log's contents: a new log (even at a freed log's address)
  // and clear() get a fresh serial, so per-thread report caches never go stale.
  uint64_t serial() const { return serial_.load(std::memory_order_acquire); }

 private:
  std::atomic<uint64_t> serial_;
  mutable std::mutex mutex_;
  std::map<std::string, std::string> missing_;
  std::map<std::string, std::string> violations_;
  std::map<std::string, bool> ran_;
  std::set<std::string> striping_;  // ids reported at least once by a pixel-striping stub
};

// Makes `log` the current thread's log while in scope (the job runner does
// this on every worker before running student code).
class ScopedTaskLog {
 public:
  explicit ScopedTaskLog(TaskLog* log);
  ~ScopedTaskLog();
  ScopedTaskLog(const ScopedTaskLog&) = delete;
  ScopedTaskLog& operator=(const ScopedTaskLog&) = delete;

 private:
  TaskLog* previous_;
};

// The current thread's log (null if none): parallel framework code hands it to its workers.
LIGHTLAB_FRAMEWORK_ONLY TaskLog* currentTaskLog();

// Records a missing task in the current thread's log and, if `marksPixels`,
// flags the current sample. Safe to call with no log installed. Cheap when
// called per ray: after the first report of an id to a log, a thread skips the lock.
// The one function here that student code (the stubs) calls.
void reportMissingTask(const char* id, const char* what, bool marksPixels = true);
// Reads and clears the per-thread flag "the current sample used a stub".
LIGHTLAB_FRAMEWORK_ONLY bool takeStubFlag();

// Every task ID reported anywhere in the process (with or without a log)
// since the last call, which clears the record: the task-test program asks
// after each test which stubs it ran, so the grader can mark that task "not
// implemented" even where the stub's fallback passes the test.
LIGHTLAB_FRAMEWORK_ONLY std::set<std::string> takeTasksReported();

}  // namespace ll

#define LIGHTLAB_TODO(id, what) ::ll::reportMissingTask(id, what)
// For a stub whose fallback gives exactly the right answer, only slower (an
// accelerator falling back to brute force): the task is reported, the
// pixels are not striped.
#define LIGHTLAB_TODO_EXACT(id, what) ::ll::reportMissingTask(id, what, false)
