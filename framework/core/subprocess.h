// Runs another program -- how the grader runs student code (renders, task
// tests), so that an exit, a crash, an endless loop or a flood of output in
// it costs one test, never the grader:
//   - its own process group, killed at the time limit and when it ends (with
//     every process left behind: with a sandbox user, all of that user's);
//   - stdout and stderr merged into one pipe that this process reads and
//     caps (the first and last kilobytes are kept, the rest counted);
//   - optionally a result channel (tests/task_tests_main.cpp): a pipe on fd
//     3 that only the child's harness may write lines to, prefixed with a
//     key it reads from fd 4 before anything else runs;
//   - optionally as another user, with limits on memory, processes, CPU time
//     and file size (the autograder, when run as root).
#pragma once

#include <sys/types.h>

#include <functional>
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
  std::string output;     // stdout and stderr as they came, capped (see ChildSpec)
  size_t outputDropped = 0;  // bytes left out of `output` (marked "[... N bytes ...]" in it)
  // One line for a person: "exited with 0", "crashed (signal 11, SIGSEGV)", "timed out after 60 s".
  std::string describe() const;
  bool succeeded() const { return started && !timedOut && signal == 0 && exitCode == 0; }
};

// Where and as whom a child runs. uid 0 (or not running as root): as this user.
struct Sandbox {
  uid_t uid = 0;
  gid_t gid = 0;
  unsigned long long memoryBytes = 0;  // address space (RLIMIT_AS); 0: no limit
  unsigned long long processes = 0;    // processes and threads of the user (RLIMIT_NPROC); 0: no limit
  unsigned long long fileBytes = 0;    // largest file it may write (RLIMIT_FSIZE); 0: no limit
  bool active() const { return uid != 0; }
};

struct ChildSpec {
  std::vector<std::string> argv;  // argv[0]: a path, or a name looked up in PATH
  std::vector<std::string> env;   // "NAME=value" added to this process's environment
  std::string workDir;            // "" = this process's
  double timeoutSeconds = 0.0;    // <= 0: no limit
  double firstLineTimeout = 0.0;  // > 0: killed if no channel line came this long after the start
  Sandbox sandbox;
  size_t outputHead = 48 * 1024, outputTail = 16 * 1024;  // bytes of output kept from the start and the end
  // The result channel: when `channelKey` is set, the child gets LIGHTLAB_RESULT_FD=3 and
  // LIGHTLAB_RESULT_KEY_FD=4; each complete line on fd 3 that starts with the key goes (without
  // it) to onLine, whose return value, if > 0, moves the deadline to that many seconds from now
  // (never past timeoutSeconds from the start).
  std::string channelKey;
  std::function<double(const std::string& line)> onLine;
};

SubprocessResult runChild(const ChildSpec& spec);

// Kills every process of `uid` (not root): what a sandboxed child may leave behind.
void killUserProcesses(uid_t uid);

// A random key for a result channel (hex).
std::string randomKey();

// The running program's own path (/proc/self/exe), for running itself.
std::string currentExecutable();

// A whole text file ("" if it cannot be read).
std::string readTextFile(const std::string& path);

}  // namespace ll
