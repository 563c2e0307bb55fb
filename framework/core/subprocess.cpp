#include "core/subprocess.h"

#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

extern char** environ;

namespace ll {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// argv[0] as a path: itself if it holds a '/', else found in PATH ("" if nowhere).
std::string resolveProgram(const std::string& name) {
  if (name.find('/') != std::string::npos) return name;
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

// Output kept as the first `head` bytes and the last `tail` bytes.
class CappedOutput {
 public:
  CappedOutput(size_t head, size_t tail) : headLimit_(head), tailLimit_(tail) {}
  void add(const char* data, size_t n) {
    const size_t toHead = std::min(n, headLimit_ - std::min(headLimit_, head_.size()));
    head_.append(data, toHead);
    if (toHead == n) return;
    tail_.append(data + toHead, n - toHead);
    if (tail_.size() > 2 * tailLimit_ + 4096) {
      dropped_ += tail_.size() - tailLimit_;
      tail_.erase(0, tail_.size() - tailLimit_);
    }
  }
  std::string text(size_t& dropped) {
    if (tail_.size() > tailLimit_) {
      dropped_ += tail_.size() - tailLimit_;
      tail_.erase(0, tail_.size() - tailLimit_);
    }
    dropped = dropped_;
    if (dropped_ == 0) return head_ + tail_;
    return head_ + "\n[... " + std::to_string(dropped_) + " bytes of output left out ...]\n" + tail_;
  }

 private:
  size_t headLimit_, tailLimit_;
  std::string head_, tail_;
  size_t dropped_ = 0;
};

void setLimit(int resource, unsigned long long value) {
  if (value == 0) return;
  const rlimit r{static_cast<rlim_t>(value), static_cast<rlim_t>(value)};
  setrlimit(resource, &r);
}

// Reads what is there (non-blocking); false at end of file.
bool drain(int fd, const std::function<void(const char*, size_t)>& sink) {
  char buffer[65536];
  for (;;) {
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n > 0) {
      sink(buffer, static_cast<size_t>(n));
      continue;
    }
    if (n == 0) return false;
    return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR;
  }
}

}  // namespace

std::string SubprocessResult::describe() const {
  if (!started) return "could not start: " + error;
  if (timedOut) {
    std::ostringstream s;
    s << "timed out after " << static_cast<int>(seconds + 0.5) << " s";
    return s.str();
  }
  if (signal != 0) return "crashed (signal " + std::to_string(signal) + ", " + sigabbrev_np(signal) + ")";
  return "exited with " + std::to_string(exitCode);
}

void killUserProcesses(uid_t uid) {
  if (uid == 0 || geteuid() != 0) return;
  const pid_t pid = fork();
  if (pid == 0) {
    // As that user, signal every process it may signal: all of its own (never root's, never ours).
    if (setuid(uid) != 0) _exit(1);
    for (int round = 0; round < 4; ++round) {
      kill(-1, SIGKILL);
      usleep(2000);
    }
    _exit(0);
  }
  if (pid > 0) waitpid(pid, nullptr, 0);
}

std::string randomKey() {
  unsigned char bytes[16] = {};
  std::ifstream in("/dev/urandom", std::ios::binary);
  in.read(reinterpret_cast<char*>(bytes), sizeof bytes);
  static const char* hex = "0123456789abcdef";
  std::string key;
  for (unsigned char b : bytes) {
    key += hex[b >> 4];
    key += hex[b & 15];
  }
  return key;
}

SubprocessResult runChild(const ChildSpec& spec) {
  SubprocessResult r;
  if (spec.argv.empty()) {
    r.error = "no program";
    return r;
  }
  const std::string program = resolveProgram(spec.argv[0]);
  if (program.empty() || access(program.c_str(), X_OK) != 0) {
    r.error = spec.argv[0] + ": no such program";
    return r;
  }
  // Everything the child needs, prepared before fork (after it, only async-signal-safe calls).
  std::vector<char*> args;
  for (const std::string& a : spec.argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<std::string> envStore;
  for (char** e = environ; *e != nullptr; ++e) envStore.emplace_back(*e);
  const bool channel = !spec.channelKey.empty();
  std::vector<std::string> extra = spec.env;
  if (channel) {
    extra.emplace_back("LIGHTLAB_RESULT_FD=3");
    extra.emplace_back("LIGHTLAB_RESULT_KEY_FD=4");
  }
  for (const std::string& e : extra) {
    const std::string name = e.substr(0, e.find('=') + 1);
    envStore.erase(std::remove_if(envStore.begin(), envStore.end(),
                                  [&](const std::string& x) { return x.rfind(name, 0) == 0; }),
                   envStore.end());
    envStore.push_back(e);
  }
  std::vector<char*> env;
  for (const std::string& e : envStore) env.push_back(const_cast<char*>(e.c_str()));
  env.push_back(nullptr);

  int out[2] = {-1, -1}, results[2] = {-1, -1}, key[2] = {-1, -1};
  if (pipe2(out, O_CLOEXEC) != 0 || (channel && (pipe2(results, O_CLOEXEC) != 0 || pipe2(key, O_CLOEXEC) != 0))) {
    r.error = std::string("pipe: ") + std::strerror(errno);
    return r;
  }
  const int devNull = open("/dev/null", O_RDONLY | O_CLOEXEC);
  const bool dropPrivileges = spec.sandbox.active() && geteuid() == 0;
  const Sandbox box = spec.sandbox;
  const char* workDir = spec.workDir.empty() ? nullptr : spec.workDir.c_str();

  const auto start = Clock::now();
  const pid_t pid = fork();
  if (pid < 0) {
    r.error = std::string("fork: ") + std::strerror(errno);
    return r;
  }
  if (pid == 0) {
    setpgid(0, 0);  // its own group: a timeout kills its children too
    const int o = fcntl(out[1], F_DUPFD, 10);
    const int rw = channel ? fcntl(results[1], F_DUPFD, 10) : -1;
    const int kr = channel ? fcntl(key[0], F_DUPFD, 10) : -1;
    dup2(devNull, 0);
    dup2(o, 1);
    dup2(o, 2);
    if (channel) {
      dup2(rw, 3);
      dup2(kr, 4);
    }
    close_range(channel ? 5 : 3, ~0U, 0);
    const rlimit noCore{0, 0};
    setrlimit(RLIMIT_CORE, &noCore);  // no core files
    setLimit(RLIMIT_AS, box.memoryBytes);
    setLimit(RLIMIT_FSIZE, box.fileBytes);
    if (dropPrivileges) {
      setLimit(RLIMIT_NPROC, box.processes);
      if (setgroups(0, nullptr) != 0 || setgid(box.gid) != 0 || setuid(box.uid) != 0) _exit(126);
    }
    if (workDir && chdir(workDir) != 0) _exit(126);
    execve(program.c_str(), args.data(), env.data());
    _exit(127);
  }
  r.started = true;
  close(out[1]);
  if (devNull >= 0) close(devNull);
  if (channel) {
    close(results[1]);
    close(key[0]);
    const std::string k = spec.channelKey + "\n";
    if (write(key[1], k.data(), k.size()) < 0) { /* the child is gone; its status will say why */ }
    close(key[1]);
    fcntl(results[0], F_SETFL, O_NONBLOCK);
  }
  fcntl(out[0], F_SETFL, O_NONBLOCK);

  CappedOutput output(spec.outputHead, spec.outputTail);
  std::string pending;  // channel bytes not yet ending in a newline
  const double limit = spec.timeoutSeconds > 0.0 ? spec.timeoutSeconds : 1e30;
  double deadline = spec.firstLineTimeout > 0.0 ? std::min(limit, spec.firstLineTimeout) : limit;  // from start
  const auto onOutput = [&](const char* d, size_t n) { output.add(d, n); };
  const auto onChannel = [&](const char* d, size_t n) {
    pending.append(d, n);
    size_t at;
    while ((at = pending.find('\n')) != std::string::npos) {
      std::string line = pending.substr(0, at);
      pending.erase(0, at + 1);
      const std::string prefix = spec.channelKey + " ";
      if (line.rfind(prefix, 0) != 0 || !spec.onLine) continue;  // not the harness's
      const double extend = spec.onLine(line.substr(prefix.size()));
      if (extend > 0.0) deadline = std::min(limit, since(start) + extend);
    }
    if (pending.size() > (1u << 24)) pending.clear();  // no newline in 16 MiB: not the harness
  };
  bool outOpen = true, resultsOpen = channel;
  int status = 0;
  bool exited = false;
  for (;;) {
    pollfd fds[2];
    nfds_t n = 0;
    if (outOpen) fds[n++] = {out[0], POLLIN, 0};
    if (resultsOpen) fds[n++] = {results[0], POLLIN, 0};
    const double left = deadline - since(start);
    const int wait = static_cast<int>(std::clamp(left * 1000.0, 0.0, 50.0));
    if (n > 0) poll(fds, n, wait);
    else usleep(static_cast<useconds_t>(wait) * 1000u);
    if (outOpen) outOpen = drain(out[0], onOutput);
    if (resultsOpen) resultsOpen = drain(results[0], onChannel);
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) {
      exited = true;
      break;
    }
    if (since(start) > deadline) break;
  }
  // Whatever is left of it goes now: its group, and with a sandbox every process of that user.
  kill(-pid, SIGKILL);
  if (dropPrivileges) killUserProcesses(box.uid);
  if (!exited) {
    waitpid(pid, &status, 0);
    r.timedOut = true;
  }
  r.seconds = since(start);
  // The last of the output (bounded: a grandchild outside the group may hold the pipe open).
  const auto drainUntil = Clock::now() + std::chrono::milliseconds(200);
  while ((outOpen || resultsOpen) && Clock::now() < drainUntil) {
    if (outOpen) outOpen = drain(out[0], onOutput);
    if (resultsOpen) resultsOpen = drain(results[0], onChannel);
    if (outOpen || resultsOpen) usleep(5000);
  }
  close(out[0]);
  if (channel) close(results[0]);
  if (!r.timedOut) {
    if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    if (r.exitCode == 126 || r.exitCode == 127) r.error = "could not run " + program;
  }
  r.output = output.text(r.outputDropped);
  return r;
}

std::string currentExecutable() {
  char buffer[4096];
  const ssize_t n = readlink("/proc/self/exe", buffer, sizeof(buffer) - 1);
  if (n <= 0) return "lightlab";
  return std::string(buffer, static_cast<size_t>(n));
}

std::string readTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace ll
