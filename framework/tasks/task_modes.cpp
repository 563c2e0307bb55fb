#include "tasks/task_modes.h"

#include <array>
#include <atomic>
#include <sstream>

#include "core/error.h"
#include "tasks/task_catalog.h"

namespace ll::tasks {

namespace {
constexpr size_t kMaxTasks = 64;
std::array<std::atomic<unsigned char>, kMaxTasks> gModes{};  // Mode::Auto is 0

size_t slot(int task) {
  if (task < 0 || static_cast<size_t>(task) >= taskCatalog().size() || static_cast<size_t>(task) >= kMaxTasks)
    throw std::out_of_range("task index " + std::to_string(task));
  return static_cast<size_t>(task);
}
}  // namespace

bool modulesEnabled() {
#ifdef LIGHTLAB_TASK_MODULES
  return true;
#else
  return false;
#endif
}

Mode mode(int task) { return static_cast<Mode>(gModes[slot(task)].load(std::memory_order_relaxed)); }

void setMode(int task, Mode m) { gModes[slot(task)].store(static_cast<unsigned char>(m), std::memory_order_relaxed); }

void setAllModes(Mode m) {
  for (size_t i = 0; i < taskCatalog().size(); ++i) setMode(static_cast<int>(i), m);
}

void isolateTask(int owner) {
  setAllModes(Mode::Reference);
  setMode(owner, Mode::Student);
}

void useReferences(const std::string& list) {
  std::vector<int> chosen;
  std::istringstream in(list);
  std::string item;
  const auto catalog = taskCatalog();
  while (std::getline(in, item, ',')) {
    while (!item.empty() && item.front() == ' ') item.erase(item.begin());
    while (!item.empty() && item.back() == ' ') item.pop_back();
    if (item.empty() || item == "none") continue;
    if (item == "all") {
      for (size_t i = 0; i < catalog.size(); ++i) chosen.push_back(static_cast<int>(i));
      continue;
    }
    bool assignment = false;  // "A2": every task of A2
    for (size_t i = 0; i < catalog.size(); ++i)
      if (catalog[i].assignment() == item) {
        chosen.push_back(static_cast<int>(i));
        assignment = true;
      }
    if (assignment) continue;
    if (findTask(item) < 0) {
      std::vector<std::string> known;
      for (const TaskInfo& t : catalog) known.emplace_back(t.id);
      throwUserError("--reference: unknown task '" + item + "' (allowed: " + joinNames(known) +
                     ", an assignment such as A2, all, none)");
    }
    chosen.push_back(findTask(item));
  }
  setAllModes(Mode::Auto);
  for (int t : chosen) setMode(t, Mode::Reference);
}

std::string referenceList() {
  std::vector<std::string> ids;
  for (size_t i = 0; i < taskCatalog().size(); ++i)
    if (mode(static_cast<int>(i)) == Mode::Reference) ids.emplace_back(taskCatalog()[i].id);
  return joinNames(ids, ",");
}

std::string stubOutcome(const std::string& id, bool sameImage, bool striped) {
  const int t = findTask(id);
  const std::string stripes = sameImage ? " (the same picture)" : striped ? "; those pixels are striped magenta" : "";
  if (t >= 0 && mode(t) == Mode::Student) return "your stub ran (--isolate)" + stripes;
  return "its reference stood in" + stripes;
}

}  // namespace ll::tasks
