// main() of lightlab_task_tests: GoogleTest, plus the harness of the task
// tests.
//
// Each test belongs to the task its suite names (A2_3_RayTriangle.X grades
// A2.3; suites without a task ID, like A2_Scene, test the framework). While
// a test runs, its task runs the student's code and every other task its
// reference (tasks::isolateTask), so a test never fails for another task's
// stub or bug, in the student tree as in grading. After the test, a stub of
// its task that ran, or a rule its task's code broke (using the framework's
// own answer to it), fails the test with that reason.
//
// For the grader (framework/grading/grader.cpp), the harness reports each
// test on a channel only it writes: with LIGHTLAB_RESULT_FD=N and
// LIGHTLAB_RESULT_KEY_FD=K set, it reads a key from K before any test runs
// (the grader writes it and closes its end) and writes to N one line
//   <key> start <test>
// when a test starts and
//   <key> end {"test": ..., "status": "passed|failed|skipped", "failures": [...],
//              "stubs": [...], "violations": {...}, "calls": [task IDs], "seconds": ...}
// when it ends. Student code runs in this process but never learns the key,
// so it cannot write a result; an exit, a crash or a hang in a test leaves
// that test without an "end" line, and the grader fails it (and reruns the rest).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "render/student_task.h"
#include "tasks/crash_report.h"
#include "tasks/task_calls.h"
#include "tasks/task_catalog.h"
#include "tasks/task_modes.h"

namespace {

// The channel (internal linkage: nothing outside this file can name it).
int gResultFd = -1;
bool gHarnessFailure = false;  // the harness is adding a failure (always printed)
std::string gKey;

void openChannel() {
  const char* fd = std::getenv("LIGHTLAB_RESULT_FD");
  const char* keyFd = std::getenv("LIGHTLAB_RESULT_KEY_FD");
  if (!fd || !keyFd) return;
  const int k = std::atoi(keyFd);
  char buffer[128];
  ssize_t n = 0, got = 0;
  while (got < static_cast<ssize_t>(sizeof buffer) - 1 && (n = read(k, buffer + got, sizeof buffer - 1 - got)) > 0)
    got += n;
  close(k);
  buffer[got > 0 ? got : 0] = '\0';
  gKey = buffer;
  while (!gKey.empty() && (gKey.back() == '\n' || gKey.back() == ' ')) gKey.pop_back();
  gResultFd = std::atoi(fd);
  unsetenv("LIGHTLAB_RESULT_KEY_FD");
  unsetenv("LIGHTLAB_RESULT_FD");
}

void send(const std::string& line) {
  if (gResultFd < 0 || gKey.empty()) return;
  const std::string text = gKey + " " + line + "\n";
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = write(gResultFd, text.data() + done, text.size() - done);
    if (n <= 0) return;
    done += static_cast<size_t>(n);
  }
}

class TaskHarness : public testing::EmptyTestEventListener {
 public:
  void OnTestStart(const testing::TestInfo& info) override {
    owner_ = ll::tasks::taskOfTestSuite(info.test_suite_name());
    if (owner_ >= 0) ll::tasks::isolateTask(owner_);
    else ll::tasks::setAllModes(ll::tasks::Mode::Auto);
    ll::takeTasksReported();
    ll::tasks::takeViolations();
    ll::tasks::takeTasksCalled();
    start_ = std::chrono::steady_clock::now();
    send("start " + name(info));
  }

  void OnTestEnd(const testing::TestInfo& info) override {
    const std::set<std::string> stubs = ll::takeTasksReported();
    const std::map<std::string, std::string> violations = ll::tasks::takeViolations();
    const std::vector<std::string> called = ll::tasks::takeTasksCalled();
    if (owner_ >= 0) {
      const std::string id = ll::tasks::taskCatalog()[static_cast<size_t>(owner_)].id;
      // Failures added here are the test's own (it is still the current test); this listener
      // runs before the printer, so the test prints as failed.
      gHarnessFailure = true;
      if (violations.count(id)) ADD_FAILURE() << id << ": " << violations.at(id);
      else if (stubs.count(id) && info.result()->Passed() && !info.result()->Skipped())
        ADD_FAILURE() << id << " not implemented: its stub ran in this test";
      else if (stubs.count(id) && info.result()->Failed())  // printed only: the failures are the grader's to count
        std::printf("%s not implemented: its stub ran in this test, so the failures above are its placeholder's "
                    "answers; write %s first\n",
                    id.c_str(), ll::tasks::taskCatalog()[static_cast<size_t>(owner_)].path().c_str());
      gHarnessFailure = false;
    }
    const testing::TestResult& r = *info.result();
    nlohmann::json failures = nlohmann::json::array();
    for (int i = 0; i < r.total_part_count(); ++i) {
      const testing::TestPartResult& part = r.GetTestPartResult(i);
      if (!part.failed()) continue;
      std::string where = part.file_name() ? part.file_name() : "";
      if (part.line_number() >= 0) where += ":" + std::to_string(part.line_number());
      failures.push_back({{"where", where}, {"message", part.message()}});
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const char* status = r.Skipped() ? "skipped" : r.Failed() ? "failed" : "passed";
    send("end " + nlohmann::json{{"test", name(info)},
                                 {"status", status},
                                 {"failures", failures},
                                 {"stubs", stubs},
                                 {"violations", violations},
                                 {"calls", called},
                                 {"seconds", seconds}}
                      .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    ll::tasks::setAllModes(ll::tasks::Mode::Auto);
  }

 private:
  static std::string name(const testing::TestInfo& info) {
    return std::string(info.test_suite_name()) + "." + info.name();
  }
  int owner_ = -1;
  std::chrono::steady_clock::time_point start_;
};

// GoogleTest's printer, showing at most kShownFailures failed checks per test: a test that loops over
// 512 inputs printed a thousand lines for one stub, burying what to do. The rest are counted; the
// grader's channel (above) still gets every failure, and the harness's own always shows.
class CappedPrinter : public testing::EmptyTestEventListener {
 public:
  static constexpr int kShownFailures = 5;
  explicit CappedPrinter(testing::TestEventListener* inner) : inner_(inner) {}
  ~CappedPrinter() override { delete inner_; }
  CappedPrinter(const CappedPrinter&) = delete;
  CappedPrinter& operator=(const CappedPrinter&) = delete;

  void OnTestProgramStart(const testing::UnitTest& u) override { inner_->OnTestProgramStart(u); }
  void OnTestIterationStart(const testing::UnitTest& u, int i) override { inner_->OnTestIterationStart(u, i); }
  void OnEnvironmentsSetUpStart(const testing::UnitTest& u) override { inner_->OnEnvironmentsSetUpStart(u); }
  void OnEnvironmentsSetUpEnd(const testing::UnitTest& u) override { inner_->OnEnvironmentsSetUpEnd(u); }
  void OnTestSuiteStart(const testing::TestSuite& t) override { inner_->OnTestSuiteStart(t); }
#ifndef GTEST_REMOVE_LEGACY_TEST_CASEAPI_
  void OnTestCaseStart(const testing::TestCase& t) override { inner_->OnTestCaseStart(t); }
  void OnTestCaseEnd(const testing::TestCase& t) override { inner_->OnTestCaseEnd(t); }
#endif
  void OnTestStart(const testing::TestInfo& t) override {
    shown_ = hidden_ = 0;
    inner_->OnTestStart(t);
  }
  void OnTestDisabled(const testing::TestInfo& t) override { inner_->OnTestDisabled(t); }
  void OnTestPartResult(const testing::TestPartResult& r) override {
    if (r.failed() && !gHarnessFailure && ++shown_ > kShownFailures) {
      ++hidden_;
      return;
    }
    inner_->OnTestPartResult(r);
  }
  void OnTestEnd(const testing::TestInfo& t) override {
    if (hidden_ > 0)
      std::printf("... and %d more failed checks in this test, not shown (the first %d are above)\n", hidden_,
                  kShownFailures);
    inner_->OnTestEnd(t);
  }
  void OnTestSuiteEnd(const testing::TestSuite& t) override { inner_->OnTestSuiteEnd(t); }
  void OnEnvironmentsTearDownStart(const testing::UnitTest& u) override { inner_->OnEnvironmentsTearDownStart(u); }
  void OnEnvironmentsTearDownEnd(const testing::UnitTest& u) override { inner_->OnEnvironmentsTearDownEnd(u); }
  void OnTestIterationEnd(const testing::UnitTest& u, int i) override { inner_->OnTestIterationEnd(u, i); }
  void OnTestProgramEnd(const testing::UnitTest& u) override { inner_->OnTestProgramEnd(u); }

 private:
  testing::TestEventListener* inner_;
  int shown_ = 0, hidden_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  // A crash in a test names the task whose code crashed (the grader shows the program's last output).
  if (ll::tasks::modulesEnabled()) ll::tasks::installCrashReport();
  openChannel();
  testing::InitGoogleTest(&argc, argv);
  // The harness before the printer, so that its failures show in the test's verdict.
  testing::TestEventListeners& listeners = testing::UnitTest::GetInstance()->listeners();
  testing::TestEventListener* printer = listeners.Release(listeners.default_result_printer());
  listeners.Append(new TaskHarness);
  if (printer) listeners.Append(new CappedPrinter(printer));
  return RUN_ALL_TESTS();
}
