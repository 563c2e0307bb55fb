// lightlab check-module MODULE --task ID
// The build runs this on every task module it links (the student
// configuration, and the autograder's build of a submission): the module may
// export nothing but its entry, so that no student file can define a
// framework or grader symbol; and it must load in this program -- every
// symbol it uses defined, none of them framework-only -- and hold its task's
// functions. Loading runs the module's own code (its static initialisers), so
// that part runs in a child process with a time limit, whose processes are
// all killed afterwards. Prints each problem as one line; exits 1 if any.
#include <cstdio>

#include "cli/commands.h"
#include "core/subprocess.h"
#include "tasks/task_catalog.h"
#include "tasks/task_modules.h"

namespace ll::cli {

namespace {
struct CheckOptions {
  std::string module, task;
  bool loadOnly = false;
};
}  // namespace

Command addCheckModuleCommand(CLI::App& app, const GlobalOptions&) {
  auto o = std::make_shared<CheckOptions>();
  CLI::App* cmd = app.add_subcommand("check-module", "Check a built task module (run by the build)");
  cmd->group("");  // a build step, not for people
  cmd->add_option("module", o->module, "The task module (lightlab_<ID>.so)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--task", o->task, "Its task ID, e.g. A2.3")->required();
  cmd->add_flag("--load-only", o->loadOnly, "Only load it, in this process (what the check runs in a child)");
  return [o]() {
    const int task = tasks::requireTask(o->task);
    std::vector<std::string> problems;
    bool failed = false;  // the child printed its own problems
    if (o->loadOnly) {
      problems = tasks::checkModuleLoads(o->module, task);
    } else {
      problems = tasks::checkModuleExports(o->module, task);
      ChildSpec c;
      c.argv = {currentExecutable(), "--quiet", "check-module", o->module, "--task", o->task, "--load-only"};
      c.timeoutSeconds = 30.0;
      const SubprocessResult run = runChild(c);
      if (!run.output.empty()) std::fputs(run.output.c_str(), stderr);
      if (run.timedOut || run.signal != 0)
        problems.push_back(o->module + " does not load: loading it " + run.describe() +
                           " (code that runs when the module loads, such as a global's constructor?)");
      else if (run.exitCode != 0 && run.output.empty())
        problems.push_back(o->module + " does not load (" + run.describe() + ")");
      else if (run.exitCode != 0)
        failed = true;  // its problems are printed above
    }
    for (const std::string& p : problems) std::fprintf(stderr, "lightlab: error: %s\n", p.c_str());
    if (failed || !problems.empty()) throw CLI::RuntimeError(1);
  };
}

}  // namespace ll::cli
