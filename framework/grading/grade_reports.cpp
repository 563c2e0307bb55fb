// Scores, the terminal table, JUnit XML and Gradescope's results.json.
// The HTML report is in html_report.cpp.
#include "grading/grade_reports.h"

#include "grading/report_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/markup.h"

namespace ll::grading {

namespace {


std::string formatFixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// "A2 Ray casting" (or just "A2" without a title).
std::string assignmentName(const GradeResult& result) {
  return result.title.empty() ? result.assignment : result.assignment + " " + result.title;
}

// Columns a UTF-8 string takes (code points; good enough for titles).
size_t displayWidth(const std::string& s) {
  size_t n = 0;
  for (char c : s)
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) ++n;
  return n;
}

std::string padRight(const std::string& s, size_t width) {
  size_t w = displayWidth(s);
  return w >= width ? s : s + std::string(width - w, ' ');
}

std::string padLeft(const std::string& s, size_t width) {
  size_t w = displayWidth(s);
  return w >= width ? s : std::string(width - w, ' ') + s;
}


std::string coloured(const std::string& text, Status s, bool colour) {
  return colour ? statusStyle(s).ansiColour + text + "\x1b[0m" : text;
}

double totalWeight(const TaskResult& task) {
  double w = 0.0;
  for (const TestResult& t : task.tests) w += t.weight;
  return w;
}

double round4(double v) {
  return std::round(v * 1e4) / 1e4;
}



}  // namespace

const StatusStyle& statusStyle(Status s) {
  static const StatusStyle styles[] = {
      {"passed", "passed", "\x1b[32m"},                    // green
      {"failed", "failed", "\x1b[31m"},                    // red
      {"not implemented", "notimpl", "\x1b[33m"},          // yellow
      {"error", "error", "\x1b[31m"},                      // red
  };
  return styles[static_cast<int>(s)];
}

void finalizeScores(GradeResult& result) {
  result.score = 0.0;
  result.maxScore = 0.0;
  for (TaskResult& task : result.tasks) {
    double all = 0.0, passed = 0.0;
    bool allPassed = !task.tests.empty(), notImplemented = false, error = false;
    for (const TestResult& t : task.tests) {
      all += t.weight;
      if (t.status == Status::Passed) passed += t.weight;
      allPassed = allPassed && t.status == Status::Passed;
      notImplemented = notImplemented || t.status == Status::NotImplemented;
      error = error || t.status == Status::Error;
    }
    // A task whose stub ran anywhere scores nothing: tests that its fallback passes earn no points.
    task.score = all > 0.0 && !notImplemented ? task.points * passed / all : 0.0;
    task.status = allPassed        ? Status::Passed
                  : notImplemented ? Status::NotImplemented
                  : error          ? Status::Error
                                   : Status::Failed;
    result.score += task.score;
    if (!task.optional) result.maxScore += task.points;
  }
}

void writeTextReport(const GradeResult& result, std::FILE* out, bool colour, const std::string& reportPath) {
  const std::string bold = colour ? "\x1b[1m" : "", reset = colour ? "\x1b[0m" : "";
  std::fprintf(out, "%s%s: %s%s (seed %u, %s s)\n", bold.c_str(), assignmentName(result).c_str(),
               pointsSummary(result).c_str(),
               reset.c_str(), result.seed, formatFixed(result.seconds, 1).c_str());

  size_t idWidth = 0, titleWidth = 0, scoreWidth = 0;
  std::vector<std::string> scores;
  for (const TaskResult& task : result.tasks) {
    scores.push_back(formatNumber(task.score) + "/" + formatNumber(task.points));
    idWidth = std::max(idWidth, displayWidth(task.id));
    titleWidth = std::max(titleWidth, displayWidth(task.title));
    scoreWidth = std::max(scoreWidth, displayWidth(scores.back()));
  }
  for (size_t i = 0; i < result.tasks.size(); ++i) {
    const TaskResult& task = result.tasks[i];
    std::fprintf(out, "  %s  %s  %s  %s\n", padRight(task.id, idWidth).c_str(),
                 padRight(task.title, titleWidth).c_str(), padLeft(scores[i], scoreWidth).c_str(),
                 coloured(statusName(task.status), task.status, colour).c_str());
  }
  // Then, per task that lost points, what failed -- in full.
  for (const TaskResult& task : result.tasks) {
    if (task.status == Status::Passed) continue;
    std::fprintf(out, "\n%s%s %s: %s%s\n", bold.c_str(), task.id.c_str(), task.title.c_str(),
                 statusName(task.status), reset.c_str());
    if (!task.file.empty())
      std::fprintf(out, "  look at: %s (%s)\n", task.file.c_str(), task.functions.c_str());
    if (task.tests.empty()) std::fputs("  (no tests)\n", out);
    if (stillTheStub(task)) {  // one line, not one per check that ran the stub
      std::fprintf(out, "  %s  %s\n", coloured(statusName(Status::NotImplemented), Status::NotImplemented, colour).c_str(),
                   stubAdvice(task).c_str());
      continue;
    }
    // A stub (or a module that does not load) fails every test alike: said once, with a count.
    std::vector<std::pair<const TestResult*, int>> shown;
    for (const TestResult& t : task.tests) {
      if (t.status == Status::Passed) continue;
      auto same = std::find_if(shown.begin(), shown.end(), [&t](const auto& l) {
        return l.first->status == t.status && l.first->details.empty() && t.details.empty() &&
               l.first->message == t.message;
      });
      if (same != shown.end()) ++same->second;
      else shown.emplace_back(&t, 1);
    }
    size_t printed = 0;
    for (const auto& [t, count] : shown) {
      if (++printed > 8) {
        std::fprintf(out, "  ... and %zu more (see the report)\n", shown.size() - 8);
        break;
      }
      std::string message = shownMessage(task, *t);
      if (count > 1) message += " (" + std::to_string(count) + " tests)";
      std::fprintf(out, "  %s %s\n", coloured(statusName(t->status), t->status, colour).c_str(), message.c_str());
      // The details, indented, at most 40 lines per check.
      std::istringstream lines(t->details);
      std::string line;
      int n = 0;
      while (std::getline(lines, line)) {
        if (++n > 40) {
          std::fputs("      ...\n", out);
          break;
        }
        std::fprintf(out, "      %s\n", line.c_str());
      }
    }
  }
  if (!reportPath.empty() && result.score < result.maxScore)
    std::fprintf(out, "\nDetails, with the images side by side: %s\n", reportPath.c_str());
}

void writeJUnitReport(const GradeResult& result, const std::string& path) {
  struct Counts {
    int tests = 0, failures = 0, errors = 0;
    double seconds = 0.0;
  };
  auto count = [](const TaskResult& task) {
    Counts c;
    for (const TestResult& t : task.tests) {
      ++c.tests;
      if (t.status == Status::Failed || t.status == Status::NotImplemented) ++c.failures;
      if (t.status == Status::Error) ++c.errors;
      c.seconds += t.seconds;
    }
    return c;
  };

  Counts total;
  for (const TaskResult& task : result.tasks) {
    Counts c = count(task);
    total.tests += c.tests;
    total.failures += c.failures;
    total.errors += c.errors;
  }

  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml += "<testsuites name=\"" + escapeMarkup(result.assignment) + "\" tests=\"" +
         std::to_string(total.tests) + "\" failures=\"" + std::to_string(total.failures) +
         "\" errors=\"" + std::to_string(total.errors) + "\" time=\"" +
         formatFixed(result.seconds, 3) + "\">\n";
  for (const TaskResult& task : result.tasks) {
    Counts c = count(task);
    const std::string suite = task.title.empty() ? task.id : task.id + " " + task.title;
    xml += "  <testsuite name=\"" + escapeMarkup(suite) + "\" tests=\"" + std::to_string(c.tests) +
           "\" failures=\"" + std::to_string(c.failures) + "\" errors=\"" +
           std::to_string(c.errors) + "\" time=\"" + formatFixed(c.seconds, 3) + "\">\n";
    for (const TestResult& t : task.tests) {
      xml += "    <testcase classname=\"" + escapeMarkup(task.id) + "\" name=\"" + escapeMarkup(t.name) +
             "\" time=\"" + formatFixed(t.seconds, 3) + "\"";
      if (t.status == Status::Passed) {
        xml += "/>\n";
        continue;
      }
      const std::string message = t.message.empty() ? statusName(t.status) : t.message;
      if (t.status == Status::Error) {
        xml += ">\n      <error message=\"" + escapeMarkup(message) + "\" type=\"error\">";
        xml += escapeMarkup(t.details, true) + "</error>\n";
      } else {
        xml += ">\n      <failure message=\"" + escapeMarkup(message) + "\" type=\"" +
               statusName(t.status) + "\">";
        xml += escapeMarkup(t.details, true) + "</failure>\n";
      }
      xml += "    </testcase>\n";
    }
    xml += "  </testsuite>\n";
  }
  xml += "</testsuites>\n";
  writeTextFile(path, xml);
}

void writeGradescopeReport(const GradeResult& result, const std::string& path) {
  using nlohmann::json;
  int tasksPassed = 0;
  json tests = json::array();
  for (const TaskResult& task : result.tasks) {
    if (task.status == Status::Passed) ++tasksPassed;
    const double all = totalWeight(task);
    for (const TestResult& t : task.tests) {
      const double maxScore = all > 0.0 ? task.points * t.weight / all : 0.0;
      // As finalizeScores: nothing for a task whose stub ran.
      const bool passed = t.status == Status::Passed && task.status != Status::NotImplemented;
      std::string output = t.message;
      if (!t.details.empty()) output += (output.empty() ? "" : "\n") + t.details;
      tests.push_back({
          {"name", t.name},
          {"number", task.id},
          {"score", passed ? round4(maxScore) : 0.0},
          {"max_score", round4(maxScore)},
          {"status", passed ? "passed" : "failed"},
          {"output", output},
      });
    }
  }
  json doc = {
      {"score", round4(result.score)},
      {"execution_time", static_cast<int>(std::lround(result.seconds))},
      {"output", assignmentName(result) + ": " + formatNumber(result.score) + " / " +
                     formatNumber(result.maxScore) + " points, " + std::to_string(tasksPassed) +
                     " of " + std::to_string(result.tasks.size()) + " tasks passed (seed " +
                     std::to_string(result.seed) + ")"},
      {"visibility", "visible"},
      {"tests", tests},
  };
  // Invalid UTF-8 in test output is replaced rather than thrown on.
  writeTextFile(path, doc.dump(2, ' ', false, json::error_handler_t::replace) + "\n");
}

}  // namespace ll::grading
