// lightlab check-module MODULE --task ID
// The build runs this on every task module it links (the student
// configuration): the module must load in this program (every symbol it uses
// defined, none of them framework-only), hold its task's functions and export
// nothing but its entry, so that no student file can define a framework or
// grader symbol. Prints each problem as one line; exits 1 if there is any.
#include <cstdio>

#include "cli/commands.h"
#include "tasks/task_catalog.h"
#include "tasks/task_modules.h"

namespace ll::cli {

Command addCheckModuleCommand(CLI::App& app, const GlobalOptions&) {
  auto module = std::make_shared<std::string>();
  auto task = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("check-module", "Check a built task module (run by the build)");
  cmd->group("");  // a build step, not for people
  cmd->add_option("module", *module, "The task module (lightlab_<ID>.so)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--task", *task, "Its task ID, e.g. A2.3")->required();
  return [module, task]() {
    const std::vector<std::string> problems = tasks::checkTaskModule(*module, tasks::requireTask(*task));
    for (const std::string& p : problems) std::fprintf(stderr, "lightlab: error: %s\n", p.c_str());
    if (!problems.empty()) throw CLI::RuntimeError(1);
  };
}

}  // namespace ll::cli
