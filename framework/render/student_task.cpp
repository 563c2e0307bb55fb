#include "render/student_task.h"

#include "tasks/task_calls.h"

#include <mutex>
#include <utility>
#include <vector>

namespace ll {

namespace {
thread_local TaskLog* tCurrentLog = nullptr;
thread_local bool tStubUsed = false;
std::atomic<uint64_t> gNextSerial{1};
uint64_t nextSerial() { return gNextSerial.fetch_add(1, std::memory_order_relaxed); }

// The process-wide record of takeTasksReported; each thread skips the lock
// for ids it already recorded in the current epoch.
std::mutex gReportedMutex;
std::set<std::string> gReported;
std::atomic<uint64_t> gReportedEpoch{1};

void recordReported(const char* id) {
  thread_local uint64_t epoch = 0;
  thread_local std::vector<std::string> known;
  const uint64_t now = gReportedEpoch.load(std::memory_order_acquire);
  if (epoch != now) {
    epoch = now;
    known.clear();
  }
  for (const std::string& k : known)
    if (k == id) return;
  known.emplace_back(id);
  std::lock_guard lock(gReportedMutex);
  gReported.insert(id);
}
}  // namespace

TaskLog::TaskLog() : serial_(nextSerial()) {}

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

void TaskLog::reportViolation(const std::string& id, const std::string& message) {
  std::lock_guard lock(mutex_);
  violations_.try_emplace(id, message);
}

std::map<std::string, std::string> TaskLog::violations() const {
  std::lock_guard lock(mutex_);
  return violations_;
}

void TaskLog::noteRan(const std::string& id, bool byReference) {
  std::lock_guard lock(mutex_);
  auto [it, fresh] = ran_.try_emplace(id, byReference);
  if (!fresh) it->second = it->second && byReference;  // the student's code ran at least once: theirs
}

std::map<std::string, bool> TaskLog::ran() const {
  std::lock_guard lock(mutex_);
  return ran_;
}

std::map<std::string, std::string> TaskLog::missing() const {
  std::lock_guard lock(mutex_);
  return missing_;
}

void TaskLog::clear() {
  std::lock_guard lock(mutex_);
  missing_.clear();
  violations_.clear();
  striping_.clear();
  ran_.clear();
  serial_.store(nextSerial(), std::memory_order_release);
}

ScopedTaskLog::ScopedTaskLog(TaskLog* log) : previous_(tCurrentLog) { tCurrentLog = log; }
ScopedTaskLog::~ScopedTaskLog() { tCurrentLog = previous_; }

TaskLog* currentTaskLog() { return tCurrentLog; }

void reportMissingTask(const char* id, const char* what, bool marksPixels) {
  tasks::noteStubRan(id);
  if (marksPixels) tStubUsed = true;
  recordReported(id);
  if (!tCurrentLog) return;
  // Stubs may run once per ray: remember (log serial, id) pairs this thread
  // already reported, so the common case takes no lock. Serials, not
  // addresses: a job's log often reuses the previous job's address.
  thread_local std::vector<std::pair<uint64_t, std::string>> reported;
  const uint64_t serial = tCurrentLog->serial();
  for (const auto& [known, knownId] : reported)
    if (known == serial && knownId == id) return;
  if (reported.size() > 64) reported.clear();
  reported.emplace_back(serial, id);
  tCurrentLog->report(id, what, !marksPixels);
}

std::set<std::string> takeTasksReported() {
  std::lock_guard lock(gReportedMutex);
  std::set<std::string> out;
  out.swap(gReported);
  gReportedEpoch.fetch_add(1, std::memory_order_acq_rel);
  return out;
}

bool takeStubFlag() {
  const bool used = tStubUsed;
  tStubUsed = false;
  return used;
}

}  // namespace ll
