#include "render/student_task.h"

namespace ll {

namespace {
thread_local TaskLog* tCurrentLog = nullptr;
thread_local bool tStubUsed = false;
}  // namespace

void TaskLog::report(const std::string& id, const std::string& what) {
  std::lock_guard lock(mutex_);
  missing_.try_emplace(id, what);
}

std::map<std::string, std::string> TaskLog::missing() const {
  std::lock_guard lock(mutex_);
  return missing_;
}

void TaskLog::clear() {
  std::lock_guard lock(mutex_);
  missing_.clear();
}

ScopedTaskLog::ScopedTaskLog(TaskLog* log) : previous_(tCurrentLog) { tCurrentLog = log; }
ScopedTaskLog::~ScopedTaskLog() { tCurrentLog = previous_; }

void reportMissingTask(const char* id, const char* what) {
  tStubUsed = true;
  if (tCurrentLog) tCurrentLog->report(id, what);
}

bool takeStubFlag() {
  const bool used = tStubUsed;
  tStubUsed = false;
  return used;
}

}  // namespace ll
