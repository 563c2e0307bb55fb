// The `lightlab` command line: render, info, trace, compare, radiosity, grade, study, and gui when built with it
// (cli/command_line.h). Any bad input ends with one line on stderr and a non-zero exit status.
#include "cli/command_line.h"

int main(int argc, char** argv) { return ll::cli::runCommandLine(argc, argv); }
