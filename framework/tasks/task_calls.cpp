#include "tasks/task_calls.h"

#include <array>
#include <atomic>
#include <bitset>
#include <cstdint>
#include <cstring>
#include <mutex>

#include "render/student_task.h"
#include "tasks/task_catalog.h"

namespace ll::tasks {

namespace {
constexpr size_t kMaxTasks = 64;
thread_local bool tStubRan = false;
thread_local int tInnermost = -1;  // the task of the innermost StudentCall on this thread (-1: none)
thread_local std::array<uint16_t, kMaxTasks> tRunning{};

std::atomic<uint64_t> gCalled{0};
std::mutex gViolationsMutex;
std::map<std::string, std::string> gViolations;
}  // namespace

StudentCall::StudentCall(int task) : task_(task), savedStub_(tStubRan), savedInnermost_(tInnermost) {
  tStubRan = false;
  tInnermost = task;
  reentered_ = tRunning[static_cast<size_t>(task)] > 0;
  ++tRunning[static_cast<size_t>(task)];
}

StudentCall::~StudentCall() {
  --tRunning[static_cast<size_t>(task_)];
  tStubRan = savedStub_;
  tInnermost = savedInnermost_;
}

bool StudentCall::stubRan() const { return tStubRan; }

int innermostStudentTask() { return tInnermost; }

bool studentCodeRunning(int task) { return task >= 0 && tRunning[static_cast<size_t>(task)] > 0; }

void noteStubRan(const char* id) {
  if (tInnermost >= 0 && std::strcmp(taskCatalog()[static_cast<size_t>(tInnermost)].id, id) == 0) tStubRan = true;
}

void noteTaskCalled(int task, bool byReference) {
  const uint64_t bit = uint64_t{1} << static_cast<unsigned>(task);
  if (!(gCalled.load(std::memory_order_relaxed) & bit)) gCalled.fetch_or(bit, std::memory_order_relaxed);
  TaskLog* log = currentTaskLog();
  if (!log) return;
  thread_local const TaskLog* seenLog = nullptr;
  thread_local uint64_t seenSerial = 0, seenBits[2] = {0, 0};  // [byReference]: tasks already logged
  const uint64_t serial = log->serial();
  if (log != seenLog || serial != seenSerial) {
    seenLog = log;
    seenSerial = serial;
    seenBits[0] = seenBits[1] = 0;
  }
  if (seenBits[byReference] & bit) return;
  seenBits[byReference] |= bit;
  log->noteRan(taskCatalog()[static_cast<size_t>(task)].id, byReference);
}

std::vector<std::string> takeTasksCalled() {
  const uint64_t called = gCalled.exchange(0);
  std::vector<std::string> ids;
  for (size_t i = 0; i < taskCatalog().size(); ++i)
    if (called & (uint64_t{1} << i)) ids.emplace_back(taskCatalog()[i].id);
  return ids;
}

void answerUsed(int task, const char* function) {
  if (!studentCodeRunning(task)) return;
  const char* id = taskCatalog()[static_cast<size_t>(task)].id;
  reportViolation(task, std::string("your code calls ") + function + ", the framework's own answer to " + id +
                            ": write it yourself");
}

void reportViolation(int task, const std::string& message) {
  // Once per thread, task and render (violations may repeat per ray).
  thread_local std::bitset<kMaxTasks> seen;
  thread_local uint64_t seenSerial = 0;
  thread_local const TaskLog* seenLog = nullptr;
  TaskLog* log = currentTaskLog();
  const uint64_t serial = log ? log->serial() : 0;
  if (log != seenLog || serial != seenSerial) {
    seen.reset();
    seenLog = log;
    seenSerial = serial;
  }
  if (seen.test(static_cast<size_t>(task)) && log) return;
  seen.set(static_cast<size_t>(task));
  const std::string id = taskCatalog()[static_cast<size_t>(task)].id;
  {
    std::lock_guard lock(gViolationsMutex);
    gViolations.try_emplace(id, message);
  }
  if (log) log->reportViolation(id, message);
}

std::map<std::string, std::string> takeViolations() {
  std::lock_guard lock(gViolationsMutex);
  std::map<std::string, std::string> out;
  out.swap(gViolations);
  return out;
}

}  // namespace ll::tasks
