// The `lightlab` command line: render, info, trace, compare, radiosity, grade, study, and gui when built with it.
// Any bad input ends with one line on stderr and a non-zero exit status.
#include <cstdio>
#include <exception>
#include <map>
#include <memory>
#include <string>

#include <tbb/global_control.h>

#include "cli/commands.h"
#include "core/error.h"

int main(int argc, char** argv) {
  using namespace ll::cli;
  CLI::App app{"LightLab -- a teaching framework for realistic rendering"};
  app.require_subcommand(1);
  GlobalOptions global;
  app.add_flag("-q,--quiet", global.quiet, "No progress bars");
  app.add_option("--threads", global.threads, "Worker threads (default: all cores)")->check(CLI::Range(0, 1024));
  std::map<std::string, Command> commands = {
      {"render", addRenderCommand(app, global)},
      {"info", addInfoCommand(app, global)},
      {"trace", addTraceCommand(app, global)},
      {"compare", addCompareCommand(app, global)},
      {"radiosity", addRadiosityCommand(app, global)},
      {"grade", addGradeCommand(app, global)},
      {"study", addStudyCommand(app, global)},
      {"slides", addSlidesCommand(app, global)},
  };
#ifdef LIGHTLAB_HAVE_GUI
  commands["gui"] = addGuiCommand(app, global);
#endif
  try {
    app.parse(argc, argv);
    std::unique_ptr<tbb::global_control> threads;
    if (global.threads > 0)
      threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      static_cast<size_t>(global.threads));
    for (CLI::App* sub : app.get_subcommands()) commands.at(sub->get_name())();
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();  // a command's own verdict (e.g. compare --max), already explained
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::fprintf(stderr, "lightlab: error: %s (see lightlab --help)\n", e.what());
    return 2;
  } catch (const ll::UserError& e) {
    std::fprintf(stderr, "lightlab: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lightlab: internal error: %s\n", e.what());
    return 3;
  }
  return 0;
}
