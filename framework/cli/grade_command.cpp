// lightlab grade ASSIGNMENT [--report DIR] [--format text,html,junit,gradescope]
//                [--seed N] [--task ID] [--task-tests PATH] [--min-score P]
//                [--student-modules DIR] [--sources DIR] [--sandbox-user NAME] [--work-dir DIR]
//                [--budget S] [--test-timeout S] [--render-timeout S] [--grading-seed N]
// Grades the assignment (A1..A6, a folder name, or a grading.json) with the
// code this build holds (in the student tree: build/modules, rebuilt first from
// the files as saved): the task tests,
// the reference images and the complexity probes of
// assignments/<dir>/grading.json. Prints the score table with every failed
// check in full, and writes the reports into DIR (default
// out/grade/<assignment>): report.html, junit.xml, results.json (Gradescope).
// Exits 0 when grading ran, whatever the score (--min-score P: exit 1 below P).
// The autograder (assignments/autograder/run_autograder) passes the modules it
// built from a submission, the user to run them as, and its own test seed.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <pwd.h>
#include <unistd.h>

#include "cli/commands.h"
#include "core/error.h"
#include "core/subprocess.h"
#include "grading/grade_reports.h"
#include "grading/grader.h"
#include "tasks/module_builder.h"
#include "tasks/task_catalog.h"
#include "tasks/task_modes.h"

namespace ll::cli {

namespace fs = std::filesystem;

namespace {
using grading::TaskSpec;
struct GradeOptions {
  std::string assignment, report, task, taskTests;
  std::vector<std::string> formats = {"text", "html", "junit", "gradescope"};
  unsigned seed = 1;
  double minScore = -1.0;
  std::string studentModules, sources, sandboxUser, workDir;
  double budget = 480.0, testTimeout = 30.0, renderTimeout = 120.0;
  unsigned gradingSeed = 1;
};

// The uid and gid of `name`; throws UserError if there is no such user.
Sandbox sandboxFor(const std::string& name) {
  Sandbox s;
  if (name.empty()) return s;
  const passwd* pw = getpwnam(name.c_str());
  if (!pw) throwUserError("grade: --sandbox-user: no user '" + name + "' (create it: useradd --system " + name + ")");
  if (pw->pw_uid == 0) throwUserError("grade: --sandbox-user must not be root");
  if (geteuid() != 0) throwUserError("grade: --sandbox-user needs root (to run student code as '" + name + "')");
  s.uid = pw->pw_uid;
  s.gid = pw->pw_gid;
  s.memoryBytes = 6ull << 30;  // address space per process; TBB and glibc reserve generously
  s.processes = 512;           // processes and threads of the user at once
  s.fileBytes = 256ull << 20;  // no file larger than 256 MiB
  return s;
}
// The student tree grades the code as saved, not its last build: the graded tasks' modules are
// rebuilt first (a no-op when up to date). A task that does not compile is graded as such, with
// the compiler's output -- not by the module its last good build left.
void rebuildGradedModules(const grading::GradingSpec& spec, const std::string& onlyTask, grading::GraderOptions& g,
                          bool quiet) {
  std::vector<int> graded;
  for (const TaskSpec& t : spec.tasks)
    if (onlyTask.empty() || t.id == onlyTask)
      if (const int i = tasks::findTask(t.id); i >= 0) graded.push_back(i);
  if (graded.empty() || tasks::buildRoot().empty()) return;
  if (!quiet) std::fprintf(stderr, "lightlab: grade: building your code as saved (cmake --build %s) ...\n", tasks::buildRoot().c_str());
  if (tasks::buildTaskModules(graded, tasks::buildRoot(), tasks::sourceRoot()).ok) return;
  for (int task : graded) {  // one failed: which ones (each on its own, so one error does not hide another)
    const tasks::ModuleBuild b = tasks::buildTaskModules({task}, tasks::buildRoot(), tasks::sourceRoot());
    if (b.ok) continue;
    const std::string id = tasks::taskCatalog()[static_cast<size_t>(task)].id;
    g.buildFailures[id] = b.log;
    if (!quiet) std::fprintf(stderr, "lightlab: grade: %s does not compile: %s\n", id.c_str(), b.firstError.oneLine().c_str());
  }
}

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
  cmd->add_option("--student-modules", o->studentModules,
                  "Task modules to grade (default: this build's build/modules; the autograder's own build)");
  cmd->add_option("--sources", o->sources, "The student's files, checked for names a task forbids (default: the assignment's folder)");
  cmd->add_option("--work-dir", o->workDir, "Where student code runs and writes (default: <report>/files/work)");
  cmd->add_option("--sandbox-user", o->sandboxUser, "Run student code as this unprivileged user, with limits (root only)");
  cmd->add_option("--budget", o->budget, "Seconds for the whole grading")->capture_default_str()->check(CLI::Range(1.0, 86400.0));
  cmd->add_option("--test-timeout", o->testTimeout, "Seconds per task test")->capture_default_str()->check(CLI::Range(1.0, 3600.0));
  cmd->add_option("--render-timeout", o->renderTimeout, "Seconds per render")->capture_default_str()->check(CLI::Range(1.0, 3600.0));
  cmd->add_option("--grading-seed", o->gradingSeed, "Seed of the task tests' random inputs (the autograder uses its own)")
      ->capture_default_str();
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
    g.budgetSeconds = o->budget;
    g.testTimeout = o->testTimeout;
    g.renderTimeout = o->renderTimeout;
    g.sandbox = sandboxFor(o->sandboxUser);
    g.sourceDir = o->sources;
    g.workDir = o->workDir;
    g.childEnv.push_back("LIGHTLAB_GRADING_SEED=" + std::to_string(o->gradingSeed));
    if (!o->studentModules.empty()) {
      const std::string dir = fs::absolute(o->studentModules).string();
      g.childEnv.push_back("LIGHTLAB_STUDENT_MODULES=" + dir);
      // A task whose module did not build: the autograder leaves its compiler output instead.
      for (const TaskSpec& t : spec.tasks)
        if (!fs::exists(dir + "/lightlab_" + t.id + ".so")) {
          const std::string log = readTextFile(dir + "/lightlab_" + t.id + ".build.log");
          g.buildFailures[t.id] = log.empty() ? "no task module " + dir + "/lightlab_" + t.id + ".so" : log;
        }
    }
    if (tasks::modulesEnabled() && o->studentModules.empty() && o->taskTests.empty())
      rebuildGradedModules(spec, o->task, g, global.quiet);
    std::error_code ec;
    fs::create_directories(g.reportDir, ec);
    if (ec) throwUserError("grade: cannot create " + g.reportDir + ": " + ec.message());
    const grading::GradeResult result = grading::grade(spec, g);
    const auto wants = [&](const char* f) { return std::find(o->formats.begin(), o->formats.end(), f) != o->formats.end(); };
    if (wants("text"))
      grading::writeTextReport(result, stdout, isatty(fileno(stdout)) != 0,
                               wants("html") ? g.reportDir + "/report.html" : "");
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
