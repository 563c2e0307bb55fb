#include "cli/command_line.h"

#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include <tbb/global_control.h>

#include "core/error.h"
#include "tasks/crash_report.h"
#include "tasks/task_catalog.h"
#include "tasks/task_modes.h"

namespace ll::cli {

CommandLine::CommandLine() {
  app.require_subcommand(1);
  app.add_flag("-q,--quiet", global.quiet, "No progress bars");
  app.add_option("--threads", global.threads, "Worker threads (default: all cores)")->check(CLI::Range(0, 1024));
  app.add_option("--reference", global.reference,
                 "Run these tasks by their reference, not your code: A2.3,A2.5, an assignment (A2), all or none "
                 "(the student tree; in the solution tree every task is its reference)");
  app.add_option("--isolate", global.isolate,
                 "Run this task by your code, stub included, and every other task by its reference: what its "
                 "tests and the grader see, e.g. --isolate A2.3")
      ->excludes("--reference");
  commands = {
      {"render", addRenderCommand(app, global)},
      {"info", addInfoCommand(app, global)},
      {"trace", addTraceCommand(app, global)},
      {"compare", addCompareCommand(app, global)},
      {"radiosity", addRadiosityCommand(app, global)},
      {"grade", addGradeCommand(app, global)},
      {"study", addStudyCommand(app, global)},
      {"slides", addSlidesCommand(app, global)},
      {"check-module", addCheckModuleCommand(app, global)},
  };
#ifdef LIGHTLAB_HAVE_GUI
  commands["gui"] = addGuiCommand(app, global);
#endif
}

int runCommandLine(int argc, const char* const* argv) {
  CommandLine cl;
  if (tasks::modulesEnabled()) tasks::installCrashReport();  // a crash in student code names its task
  try {
    cl.app.parse(argc, argv);
    std::unique_ptr<tbb::global_control> threads;
    if (cl.global.threads > 0)
      threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      static_cast<size_t>(cl.global.threads));
    tasks::useReferences(cl.global.reference);
    if (!cl.global.isolate.empty()) tasks::isolateTask(tasks::requireTask(cl.global.isolate));
    for (CLI::App* sub : cl.app.get_subcommands()) cl.commands.at(sub->get_name())();
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();  // a command's own verdict (e.g. compare --max), already explained
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return cl.app.exit(e);  // --help
    // Point at the help of the command that was being parsed, which lists its options.
    std::string help = "lightlab";
    for (CLI::App* sub : cl.app.get_subcommands()) help += " " + sub->get_name();
    std::fprintf(stderr, "lightlab: error: %s (see %s --help)\n", e.what(), help.c_str());
    return 2;
  } catch (const UserError& e) {
    std::fprintf(stderr, "lightlab: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lightlab: internal error: %s\n", e.what());
    return 3;
  }
  return 0;
}

}  // namespace ll::cli
