// The `lightlab` subcommands. Each adds itself to the CLI11 app and returns
// the function that runs it after parsing. Bad input throws ll::UserError;
// main() prints it as one line and exits non-zero.
#pragma once

#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace ll::cli {

struct GlobalOptions {
  bool quiet = false;     // no progress bars
  int threads = 0;        // 0 = all cores
  std::string reference;  // tasks run by their reference (--reference A2.3,A2.5)
  std::string isolate;    // one task runs the student's code, every other its reference (--isolate A2.3)
};

using Command = std::function<void()>;

Command addRenderCommand(CLI::App& app, const GlobalOptions& global);
Command addInfoCommand(CLI::App& app, const GlobalOptions& global);
Command addTraceCommand(CLI::App& app, const GlobalOptions& global);
Command addCompareCommand(CLI::App& app, const GlobalOptions& global);
Command addRadiosityCommand(CLI::App& app, const GlobalOptions& global);
Command addGradeCommand(CLI::App& app, const GlobalOptions& global);
Command addStudyCommand(CLI::App& app, const GlobalOptions& global);
Command addSlidesCommand(CLI::App& app, const GlobalOptions& global);
Command addCheckModuleCommand(CLI::App& app, const GlobalOptions& global);
#ifdef LIGHTLAB_HAVE_GUI
Command addGuiCommand(CLI::App& app, const GlobalOptions& global);
#endif

}  // namespace ll::cli
