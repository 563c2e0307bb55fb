// Runs another program and waits for it with a time limit, its output sent to
// files: how the grader runs student code (renders, task tests) so that a
// crash or an endless loop in it costs one test, never the grader.
#pragma once

#include <string>
#include <vector>

namespace ll {

struct SubprocessResult {
  bool started = false;   // false: the program could not be started (see error)
  bool timedOut = false;  // killed after the time limit
  int exitCode = -1;      // when it exited normally
  int signal = 0;         // when a signal ended it (SIGSEGV = 11, ...), else 0
  double seconds = 0.0;   // wall time
  std::string error;      // why it did not start
  // One line for a person: "exited with 0", "crashed (signal 11, SIGSEGV)", "timed out after 60 s".
  std::string describe() const;
  bool succeeded() const { return started && !timedOut && signal == 0 && exitCode == 0; }
};

// Runs argv[0] (a path, or a name looked up in PATH) with the arguments
// argv[1..], stdout and stderr redirected to the given files (truncated;
// empty path = /dev/null), extra environment entries "NAME=value" added.
// Kills the process group after timeoutSeconds (<= 0: no limit).
SubprocessResult runSubprocess(const std::vector<std::string>& argv, const std::string& stdoutPath,
                               const std::string& stderrPath, double timeoutSeconds,
                               const std::vector<std::string>& extraEnv = {});

// The running program's own path (/proc/self/exe), for running itself.
std::string currentExecutable();

// A whole text file ("" if it cannot be read).
std::string readTextFile(const std::string& path);

}  // namespace ll
