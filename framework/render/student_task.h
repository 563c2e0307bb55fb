// How student stubs report themselves. A stub calls
//   LIGHTLAB_TODO("A2.4", "Blinn-Phong shading");
// and then returns its fallback. The render records the task as missing (the
// CLI and GUI name it), and marks the pixels that went through the stub with
// magenta stripes -- never a crash and never a silently black image.
#pragma once

#include <map>
#include <mutex>
#include <string>

namespace ll {

// Missing tasks seen during one render (thread-safe).
class TaskLog {
 public:
  void report(const std::string& id, const std::string& what);
  std::map<std::string, std::string> missing() const;  // id -> description
  void clear();

 private:
  mutable std::mutex mutex_;
  std::map<std::string, std::string> missing_;
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

// Records a missing task in the current thread's log and flags the current
// sample. Safe to call with no log installed.
void reportMissingTask(const char* id, const char* what);
// Reads and clears the per-thread flag "the current sample used a stub".
bool takeStubFlag();

}  // namespace ll

#define LIGHTLAB_TODO(id, what) ::ll::reportMissingTask(id, what)
