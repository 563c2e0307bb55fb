// lightlab grade ASSIGNMENT [--report DIR] [--format text,html,junit,gradescope]
//                [--seed N] [--task ID] [--task-tests PATH] [--min-score P]
// Grades the assignment (A1..A6, a folder name, or a grading.json) with the
// code this program was built from: the task tests, the reference images and
// the complexity probes of assignments/<dir>/grading.json. Prints the score
// table and writes the reports into DIR (default out/grade/<assignment>):
// report.html, junit.xml, results.json (Gradescope). Exits 0 when grading ran,
// whatever the score (--min-score P: exit 1 below P points).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <unistd.h>

#include "cli/commands.h"
#include "core/error.h"
#include "core/subprocess.h"
#include "grading/grade_reports.h"
#include "grading/grader.h"

namespace ll::cli {

namespace fs = std::filesystem;

namespace {
struct GradeOptions {
  std::string assignment, report, task, taskTests;
  std::vector<std::string> formats = {"text", "html", "junit", "gradescope"};
  unsigned seed = 1;
  double minScore = -1.0;
};
}  // namespace

Command addGradeCommand(CLI::App& app, const GlobalOptions& global) {
  auto o = std::make_shared<GradeOptions>();
  CLI::App* cmd = app.add_subcommand("grade", "Grade an assignment: task tests, reference images, complexity probes");
  cmd->add_option("assignment", o->assignment, "A1..A6, an assignment folder name, or a grading.json")->required();
  cmd->add_option("--report", o->report, "Folder for report.html, junit.xml, results.json (default out/grade/<A>)");
  cmd->add_option("--format", o->formats, "Reports to write: text (stdout), html, junit, gradescope")
      ->delimiter(',')
      ->check(CLI::IsMember({"text", "html", "junit", "gradescope"}))
      ->capture_default_str();
  cmd->add_option("--seed", o->seed, "Seed of every render's random streams")->capture_default_str();
  cmd->add_option("--task", o->task, "Grade only this task (e.g. A2.4)");
  cmd->add_option("--task-tests", o->taskTests, "The lightlab_task_tests program (default: beside this build's lightlab)");
  cmd->add_option("--min-score", o->minScore, "Exit with status 1 if the score is below this many points");
  return [o, &global]() {
    const std::string assignments = std::string(LIGHTLAB_SOURCE_DIR) + "/assignments";
    const std::string data = std::string(LIGHTLAB_SOURCE_DIR) + "/data";
    const grading::GradingSpec spec = grading::findGradingSpec(o->assignment, assignments, data);
    grading::GraderOptions g;
    g.dataDir = data;
    g.buildDir = LIGHTLAB_BINARY_DIR;
    g.lightlab = currentExecutable();
    g.taskTests = o->taskTests.empty() ? std::string(LIGHTLAB_BINARY_DIR) + "/tests/lightlab_task_tests" : o->taskTests;
    if (!fs::exists(g.taskTests))
      throwUserError("grade: no task tests at " + g.taskTests +
                     " (build them: cmake --build build --target lightlab_task_tests, or pass --task-tests)");
    g.reportDir = o->report.empty() ? "out/grade/" + spec.assignment : o->report;
    g.seed = o->seed;
    g.threads = global.threads;
    g.onlyTask = o->task;
    g.quiet = global.quiet;
    std::error_code ec;
    fs::create_directories(g.reportDir, ec);
    if (ec) throwUserError("grade: cannot create " + g.reportDir + ": " + ec.message());
    const grading::GradeResult result = grading::grade(spec, g);
    const auto wants = [&](const char* f) { return std::find(o->formats.begin(), o->formats.end(), f) != o->formats.end(); };
    if (wants("text")) grading::writeTextReport(result, stdout, isatty(fileno(stdout)) != 0);
    std::vector<std::string> written;
    if (wants("html")) {
      grading::writeHtmlReport(result, g.reportDir);
      written.push_back(g.reportDir + "/report.html");
    }
    if (wants("junit")) {
      grading::writeJUnitReport(result, g.reportDir + "/junit.xml");
      written.push_back(g.reportDir + "/junit.xml");
    }
    if (wants("gradescope")) {
      grading::writeGradescopeReport(result, g.reportDir + "/results.json");
      written.push_back(g.reportDir + "/results.json");
    }
    if (!written.empty() && wants("text")) std::printf("reports: %s\n", joinNames(written).c_str());
    if (o->minScore >= 0.0 && result.score < o->minScore) {
      std::fprintf(stderr, "lightlab: grade: %.4g points, below --min-score %.4g\n", result.score, o->minScore);
      throw CLI::RuntimeError(1);
    }
  };
}

}  // namespace ll::cli
