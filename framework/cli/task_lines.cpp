#include "cli/task_lines.h"

#include <cstdio>

#include "tasks/task_modes.h"

namespace ll::cli {

void printTaskLines(const std::map<std::string, std::string>& missing, const std::set<std::string>& exact,
                    bool striped, const std::map<std::string, std::string>& violations,
                    const std::string& references) {
  for (const auto& [id, what] : missing)
    std::fprintf(stderr, "lightlab: %s not implemented: %s -- %s\n", id.c_str(), what.c_str(),
                 tasks::stubOutcome(id, exact.count(id) > 0, striped).c_str());
  for (const auto& [id, what] : violations) std::fprintf(stderr, "lightlab: %s: %s\n", id.c_str(), what.c_str());
  if (!references.empty()) std::fprintf(stderr, "lightlab: by their reference (--reference): %s\n", references.c_str());
}

}  // namespace ll::cli
