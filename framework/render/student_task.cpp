#include "render/student_task.h"

#include <utility>
#include <vector>

namespace ll {

namespace {
thread_local TaskLog* tCurrentLog = nullptr;
thread_local bool tStubUsed = false;
}  // namespace

void TaskLog::report(const std::string& id, const std::string& what, bool exact) {
  std::lock_guard lock(mutex_);
  missing_.try_emplace(id, what);
  if (!exact) striping_.insert(id);
}

std::set<std::string> TaskLog::exact() const {
  std::lock_guard lock(mutex_);
  std::set<std::string> ids;
  for (const auto& [id, what] : missing_)
    if (!striping_.count(id)) ids.insert(id);
  return ids;
}

std::map<std::string, std::string> TaskLog::missing() const {
  std::lock_guard lock(mutex_);
  return missing_;
}

void TaskLog::clear() {
  std::lock_guard lock(mutex_);
  missing_.clear();
  striping_.clear();
}

ScopedTaskLog::ScopedTaskLog(TaskLog* log) : previous_(tCurrentLog) { tCurrentLog = log; }
ScopedTaskLog::~ScopedTaskLog() { tCurrentLog = previous_; }

void reportMissingTask(const char* id, const char* what, bool marksPixels) {
  if (marksPixels) tStubUsed = true;
  if (!tCurrentLog) return;
  // Stubs may run once per ray: remember (log, id) pairs this thread already
  // reported, so the common case takes no lock. Ids are few per render.
  thread_local std::vector<std::pair<const TaskLog*, std::string>> reported;
  for (const auto& [log, known] : reported)
    if (log == tCurrentLog && known == id) return;
  if (reported.size() > 64) reported.clear();
  reported.emplace_back(tCurrentLog, id);
  tCurrentLog->report(id, what, !marksPixels);
}

bool takeStubFlag() {
  const bool used = tStubUsed;
  tStubUsed = false;
  return used;
}

}  // namespace ll
