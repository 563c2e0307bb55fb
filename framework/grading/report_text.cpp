#include "grading/report_text.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "core/error.h"
#include "core/files.h"

namespace ll::grading {

std::string formatNumber(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  if (s.find('.') != std::string::npos) {
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

OptionalPoints optionalPoints(const GradeResult& result) {
  OptionalPoints o;
  for (const TaskResult& task : result.tasks)
    if (task.optional) {
      o.score += task.score;
      o.points += task.points;
    }
  return o;
}

std::string pointsSummary(const GradeResult& result) {
  const OptionalPoints o = optionalPoints(result);
  // (result.score counts every task; result.maxScore only the required ones.)
  const std::string required = formatNumber(result.score - o.score) + " / " + formatNumber(result.maxScore) + " points";
  const std::string optional = formatNumber(o.score) + " / " + formatNumber(o.points);
  if (o.points == 0.0) return required;
  if (result.maxScore == 0.0) return optional + " optional points";
  return required + " + " + optional + " optional";
}

bool stillTheStub(const TaskResult& task) {
  return !task.tests.empty() && std::all_of(task.tests.begin(), task.tests.end(), [](const TestResult& t) {
           return t.status == Status::NotImplemented;
         });
}

std::string stubAdvice(const TaskResult& task) {
  return "still the stub (all " + std::to_string(task.tests.size()) + " checks): write " +
         (task.functions.empty() ? std::string("your code") : task.functions) +
         ", then delete the LIGHTLAB_TODO lines";
}

std::string shownMessage(const TaskResult& task, const TestResult& test) {
  std::string message = test.message.empty() ? test.name : test.message;
  const std::string echo = task.id + " not implemented: ";
  if (test.status == Status::NotImplemented && message.rfind(echo, 0) == 0) message.erase(0, echo.size());
  return message;
}

void writeTextFile(const std::string& path, const std::string& text) {
  createParentDirectory(path);
  std::ofstream out(path, std::ios::binary);
  if (!out) throwUserError("cannot write " + path);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throwUserError("cannot write " + path);
}

}  // namespace ll::grading
