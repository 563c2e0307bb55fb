// The whole `lightlab` command line as one object: the CLI11 app with every
// subcommand added, ready to parse. main() runs it; the command-line fuzzer
// (tests/fuzz) parses with it without running anything.
#pragma once

#include <map>
#include <string>

#include "cli/commands.h"

namespace ll::cli {

struct CommandLine {
  CLI::App app{"LightLab -- a teaching framework for realistic rendering"};
  GlobalOptions global;
  std::map<std::string, Command> commands;  // by subcommand name; each captures `global`

  CommandLine();
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;
};

// Parses argv, runs the chosen subcommand and returns the exit status: 0 on
// success; any bad input prints one line on stderr and returns 2.
int runCommandLine(int argc, const char* const* argv);

}  // namespace ll::cli
