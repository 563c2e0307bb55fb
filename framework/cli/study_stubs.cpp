#include "cli/study_stubs.h"

#include <cstdio>

#include "core/markup.h"
#include "tasks/task_modes.h"

namespace ll::cli {

void StudyStubs::add(const std::map<std::string, std::string>& missing) { stubs_.insert(missing.begin(), missing.end()); }

void StudyStubs::print() const {
  for (const auto& [id, what] : stubs_)
    std::fprintf(stderr, "lightlab: %s not implemented: %s -- %s, in every render of this study (without stripes: a "
                 "study measures the pictures' error)\n", id.c_str(), what.c_str(), tasks::stubOutcome(id, false, false).c_str());
}

std::string StudyStubs::html() const {
  if (stubs_.empty()) return "";
  std::string items;
  for (const auto& [id, what] : stubs_)
    items += "<li>" + id + " " + escapeMarkup(what, true) + ": " + tasks::stubOutcome(id, false, false) + "</li>";
  return "<div style='background:#fde8f4;border-left:4px solid #c0398a;padding:6px 10px'><b>Not your code yet.</b> "
         "These tasks are still stubs, in every render of this study, without stripes (a study measures the "
         "pictures' error):<ul style='margin:4px 0'>" + items + "</ul></div>\n";
}

}  // namespace ll::cli
