#include "tasks/task_catalog.h"

#include <array>
#include <cctype>

#include "core/error.h"

namespace ll::tasks {

namespace {
constexpr TaskInfo kTasks[] = {
#include "tasks/task_catalog.inc"
};
}  // namespace

std::vector<std::string> TaskInfo::functionNames() const {
  std::vector<std::string> out;
  std::string current;
  for (const char* c = functions; *c; ++c) {
    if (*c == ',') {
      out.push_back(current);
      current.clear();
    } else {
      current += *c;
    }
  }
  if (!current.empty()) out.push_back(current);
  return out;
}

std::span<const TaskInfo> taskCatalog() { return kTasks; }

int findTask(std::string_view id) {
  for (size_t i = 0; i < std::size(kTasks); ++i)
    if (id == kTasks[i].id) return static_cast<int>(i);
  return -1;
}

int requireTask(std::string_view id) {
  const int i = findTask(id);
  if (i >= 0) return i;
  std::vector<std::string> known;
  for (const TaskInfo& t : kTasks) known.emplace_back(t.id);
  throwUserError("unknown task '" + std::string(id) + "' (known: " + joinNames(known) + ")");
}

int taskOfTestSuite(std::string_view suite) {
  const size_t slash = suite.rfind('/');
  if (slash != std::string_view::npos) suite = suite.substr(slash + 1);
  // A<digits>_<digits>_...
  size_t i = 0;
  if (i >= suite.size() || suite[i] != 'A') return -1;
  ++i;
  const size_t a = i;
  while (i < suite.size() && std::isdigit(static_cast<unsigned char>(suite[i]))) ++i;
  if (i == a || i >= suite.size() || suite[i] != '_') return -1;
  const size_t t = ++i;
  while (i < suite.size() && std::isdigit(static_cast<unsigned char>(suite[i]))) ++i;
  if (i == t || i >= suite.size() || suite[i] != '_') return -1;
  const std::string id = "A" + std::string(suite.substr(a, t - 1 - a)) + "." + std::string(suite.substr(t, i - t));
  return findTask(id);
}

}  // namespace ll::tasks
