#include "grading/grader.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/image.h"
#include "core/progress.h"
#include "grading/tolerance.h"
#include "metrics/image_metrics.h"
#include "metrics/pixel_ztest.h"
#include "tasks/module_builder.h"
#include "tasks/task_catalog.h"

namespace ll::grading {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

std::string fmt(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.3g", v);
  return buffer;
}

std::string safeName(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-') c = '_';
  return s;
}

// json[a][b] as a number, or `fallback` where a level is missing.
double number(const nlohmann::json& j, const char* a, const char* b, double fallback) {
  if (!j.is_object() || !j.contains(a) || !j.at(a).is_object() || !j.at(a).contains(b) || !j.at(a).at(b).is_number())
    return fallback;
  return j.at(a).at(b).get<double>();
}

nlohmann::json objectAt(const nlohmann::json& j, const char* key) {
  return j.is_object() && j.contains(key) && j.at(key).is_object() ? j.at(key) : nlohmann::json::object();
}

// The first line of `text` that mentions an error, else its first line.
std::string firstErrorLine(const std::string& text) {
  std::istringstream in(text);
  std::string line, first;
  while (std::getline(in, line)) {
    if (first.empty() && !line.empty()) first = line;
    if (line.find("error") != std::string::npos) return line;
  }
  return first;
}

// GoogleTest's filter syntax: "POS1:POS2-NEG1:NEG2", '*' and '?' wildcards.
bool globMatch(const char* p, const char* s) {
  if (*p == '\0') return *s == '\0';
  if (*p == '*') return globMatch(p + 1, s) || (*s != '\0' && globMatch(p, s + 1));
  return *s != '\0' && (*p == '?' || *p == *s) && globMatch(p + 1, s + 1);
}
bool anyMatch(const std::string& patterns, const std::string& name) {
  std::istringstream in(patterns);
  std::string p;
  while (std::getline(in, p, ':'))
    if (!p.empty() && globMatch(p.c_str(), name.c_str())) return true;
  return false;
}
bool filterMatches(const std::string& filter, const std::string& name) {
  if (filter.empty()) return true;
  const auto dash = filter.find('-');
  const std::string positive = filter.substr(0, dash), negative = dash == std::string::npos ? "" : filter.substr(dash + 1);
  return (positive.empty() || anyMatch(positive, name)) && !anyMatch(negative, name);
}

// The C++ text with comments and string literals blanked out (for the forbidden-name check).
std::string codeOnly(const std::string& src) {
  std::string out = src;
  enum { Code, Line, Block, Str, Chr } state = Code;
  for (size_t i = 0; i < out.size(); ++i) {
    const char c = out[i], next = i + 1 < out.size() ? out[i + 1] : '\0';
    switch (state) {
      case Code:
        if (c == '/' && next == '/') state = Line, out[i] = ' ';
        else if (c == '/' && next == '*') state = Block, out[i] = ' ';
        else if (c == '"') state = Str;
        else if (c == '\'') state = Chr;
        break;
      case Line:
        if (c == '\n') state = Code;
        else out[i] = ' ';
        break;
      case Block:
        if (c == '*' && next == '/') {
          out[i] = out[i + 1] = ' ';
          ++i;
          state = Code;
        } else if (c != '\n') {
          out[i] = ' ';
        }
        break;
      case Str:
      case Chr:
        if (c == '\\') {
          out[i] = ' ';
          if (i + 1 < out.size()) out[++i] = ' ';
        } else if ((state == Str && c == '"') || (state == Chr && c == '\'')) {
          state = Code;
        } else if (c != '\n') {
          out[i] = ' ';
        }
        break;
    }
  }
  return out;
}

// Where `name` occurs in `code` as a whole name: the line (1-based), or 0.
int findName(const std::string& code, const std::string& name) {
  const auto isIdent = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (size_t at = code.find(name); at != std::string::npos; at = code.find(name, at + 1)) {
    const bool startOk = at == 0 || !isIdent(code[at - 1]);
    const bool endOk = at + name.size() >= code.size() || !isIdent(code[at + name.size()]);
    if (startOk && endOk) return 1 + static_cast<int>(std::count(code.begin(), code.begin() + static_cast<long>(at), '\n'));
  }
  return 0;
}

class Grader {
 public:
  Grader(const GradingSpec& spec, const GraderOptions& o) : spec_(spec), o_(o), start_(Clock::now()) {
    files_ = o.reportDir + "/files";
    // Absolute: the renders and tests run inside work_ and are handed paths in it.
    work_ = fs::absolute(o.workDir.empty() ? files_ + "/work" : o.workDir).lexically_normal().string();
    fs::create_directories(files_);
    fs::create_directories(work_);
    if (o.sandbox.active() && geteuid() == 0) {
      // The children write here as the sandbox user; the reports stay this user's.
      if (chown(work_.c_str(), o.sandbox.uid, o.sandbox.gid) != 0)
        throwUserError("grade: cannot hand " + work_ + " to the sandbox user");
    }
  }

  GradeResult run() {
    GradeResult result;
    result.assignment = spec_.assignment;
    result.title = spec_.title;
    result.seed = o_.seed;
    result.threads = o_.threads;
    size_t total = 0;
    for (const TaskSpec& t : spec_.tasks)
      if (o_.onlyTask.empty() || t.id == o_.onlyTask) total += t.tests.size();
    if (total == 0) {
      std::vector<std::string> ids;
      for (const TaskSpec& t : spec_.tasks) ids.push_back(t.id);
      throwUserError("no task '" + o_.onlyTask + "' in " + spec_.path + " (allowed: " + joinNames(ids) + ")");
    }
    listTests();
    ProgressBar progress("grading " + spec_.assignment, static_cast<double>(total), o_.quiet);
    size_t done = 0;
    for (const TaskSpec& t : spec_.tasks) {
      if (!o_.onlyTask.empty() && t.id != o_.onlyTask) continue;
      TaskResult task;
      task.id = t.id;
      task.title = t.title;
      task.points = t.points;
      task.optional = t.optional;
      task.file = "assignments/" + fs::path(spec_.folder()).filename().string() + "/" + t.file;
      task.functions = joinNames(t.functions);
      const std::string blocked = whyNotGradable(t);
      bool notImplemented = false;
      for (const TestSpec& s : t.tests) {
        std::vector<TestResult> tests;
        if (!blocked.empty()) tests = {notRun(t, s, blocked, Status::Error)};
        else if (budgetLeft() <= 0.0) tests = {notRun(t, s, "not run: the grading time budget of " +
                                                              fmt(o_.budgetSeconds) + " s ran out", Status::Error)};
        else if (notImplemented && s.kind != "unit")
          tests = {notRun(t, s, t.id + " not implemented: " + s.kind + " check not run, the stub ran in an earlier one",
                          Status::NotImplemented)};
        else if (s.kind == "unit") tests = unit(t, s);
        else if (s.kind == "image") tests = {image(t, s)};
        else tests = {complexity(t, s)};
        for (TestResult& r : tests) {
          notImplemented = notImplemented || r.status == Status::NotImplemented;
          task.tests.push_back(std::move(r));
        }
        progress.update(static_cast<double>(++done));
      }
      result.tasks.push_back(std::move(task));
    }
    progress.finish();
    result.seconds = std::chrono::duration<double>(Clock::now() - start_).count();
    finalizeScores(result);
    return result;
  }

 private:
  double budgetLeft() const {
    return o_.budgetSeconds - std::chrono::duration<double>(Clock::now() - start_).count();
  }

  // Why none of task t's tests can run ("" if they can): its module did not build, or its file
  // uses a name the task forbids.
  std::string whyNotGradable(const TaskSpec& t) {
    if (o_.buildFailures.count(t.id))
      return t.id + ": " + t.file + " does not compile: " +
             tasks::firstCompilerError(o_.buildFailures.at(t.id), tasks::sourceRoot()).oneLine();
    if (t.forbidden.empty()) return "";
    const std::string dir = o_.sourceDir.empty() ? spec_.folder() : o_.sourceDir;
    const std::string code = codeOnly(readTextFile(dir + "/" + t.file));
    for (const std::string& name : t.forbidden)
      if (const int line = findName(code, name))
        return t.id + ": " + t.file + ":" + std::to_string(line) + " uses " + name +
               ", which this task does not allow: write it yourself";
    return "";
  }

  TestResult notRun(const TaskSpec& t, const TestSpec& s, const std::string& why, Status status) {
    TestResult r;
    r.task = t.id;
    r.kind = s.kind;
    r.weight = s.weight;
    r.name = t.id + " " + s.kind + (s.reference.empty() ? s.accelerator.empty() ? "" : " " + s.accelerator
                                                        : " " + s.reference);
    r.status = status;
    r.message = why;
    if (status == Status::Error && o_.buildFailures.count(t.id)) r.details = o_.buildFailures.at(t.id);
    return r;
  }

  // Environment and limits of every child.
  ChildSpec child(std::vector<std::string> argv, double timeout) const {
    ChildSpec c;
    c.argv = std::move(argv);
    c.env = o_.childEnv;
    c.workDir = work_;
    c.timeoutSeconds = std::max(1.0, std::min(timeout, budgetLeft()));
    c.sandbox = o_.sandbox;
    return c;
  }

  // Every test of the task-test program, "Suite.Test" (parameterized: "A2/A2_3_Scene.Fan/student").
  void listTests() {
    ChildSpec c = child({o_.taskTests, "--gtest_list_tests"}, 60.0);
    c.sandbox = Sandbox{};  // the framework's own program, no student code loads while listing
    c.workDir.clear();
    const SubprocessResult run = runChild(c);
    if (!run.succeeded())
      throwUserError("grade: " + o_.taskTests + " --gtest_list_tests " + run.describe() + ": " +
                     firstErrorLine(run.output));
    std::istringstream in(run.output);
    std::string line, suite;
    while (std::getline(in, line)) {
      const auto hash = line.find('#');
      if (hash != std::string::npos) line = line.substr(0, hash);
      while (!line.empty() && line.back() == ' ') line.pop_back();
      if (line.empty()) continue;
      if (line[0] != ' ') suite = line;  // "A2_3_RayTriangle."
      else allTests_.push_back(suite + line.substr(line.find_first_not_of(' ')));
    }
  }

  // One test's verdict from the harness's "end" line.
  TestResult unitResult(const TaskSpec& t, const nlohmann::json& end, double weight) {
    TestResult r;
    r.task = t.id;
    r.kind = "unit";
    r.weight = weight;
    const std::string test = end.value("test", "");
    r.name = t.id + " " + test;
    r.seconds = end.value("seconds", 0.0);
    std::string details;
    bool stubMentioned = false;
    for (const auto& f : end.value("failures", nlohmann::json::array())) {
      const std::string message = f.value("message", "");
      const std::string where = f.value("where", "");
      if (where.find("task_tests_main.cpp") == std::string::npos)  // not the harness's own verdict
        details += where + ":\n" + message + "\n";
      stubMentioned = stubMentioned || message.find(t.id + " not implemented") != std::string::npos;
    }
    const auto stubs = end.value("stubs", std::vector<std::string>());
    const nlohmann::json violations = objectAt(end, "violations");
    const std::string status = end.value("status", "failed");
    r.details = details;
    if (violations.contains(t.id)) {
      r.status = Status::Failed;
      r.message = t.id + ": " + test + " failed: " + violations.at(t.id).get<std::string>();
    } else if (stubMentioned || std::find(stubs.begin(), stubs.end(), t.id) != stubs.end()) {
      r.status = Status::NotImplemented;
      r.message = t.id + " not implemented: its stub ran in " + test;
      r.details.clear();
    } else if (status == "passed") {
      r.status = Status::Passed;
    } else {
      r.status = Status::Failed;
      r.message = t.id + ": " + test + " failed";
    }
    return r;
  }

  // The task's tests, each its own test result; a test that ends its process fails alone and the
  // rest of the group runs again.
  std::vector<TestResult> unit(const TaskSpec& t, const TestSpec& s) {
    const int owner = tasks::findTask(t.id);
    std::vector<std::string> todo;
    for (const std::string& name : allTests_) {
      const std::string suite = name.substr(0, name.find('.'));
      if (tasks::taskOfTestSuite(suite) == owner && filterMatches(s.filter, name)) todo.push_back(name);
    }
    std::vector<TestResult> tests;
    if (todo.empty()) {
      TestResult r = notRun(t, s, t.id + ": no task tests" + (s.filter.empty() ? "" : " match '" + s.filter + "'"),
                            Status::Error);
      return {r};
    }
    const double share = s.weight / static_cast<double>(todo.size());
    while (!todo.empty()) {
      if (budgetLeft() <= 0.0) {
        for (const std::string& name : todo) {
          TestResult r = notRun(t, s, "not run: the grading time budget of " + fmt(o_.budgetSeconds) + " s ran out",
                                Status::Error);
          r.name = t.id + " " + name;
          r.weight = share;
          tests.push_back(r);
        }
        break;
      }
      std::string filter;
      for (const std::string& name : todo) filter += (filter.empty() ? "" : ":") + name;
      std::string running;
      std::set<std::string> finished;
      ChildSpec c = child({o_.taskTests, "--gtest_filter=" + filter, "--gtest_color=no"}, o_.groupTimeout);
      c.env.push_back("LIGHTLAB_CASES_DIR=" + work_ + "/cases");  // failing rays as scenes to trace
      c.channelKey = randomKey();
      const double perTest = o_.testTimeout;
      c.onLine = [&](const std::string& line) {
        if (line.rfind("start ", 0) == 0) {
          running = line.substr(6);
        } else if (line.rfind("end ", 0) == 0) {
          try {
            const nlohmann::json end = nlohmann::json::parse(line.substr(4));
            const std::string name = end.value("test", "");
            if (std::find(todo.begin(), todo.end(), name) != todo.end() && !finished.count(name)) {
              finished.insert(name);
              if (end.value("status", "") != "skipped") tests.push_back(unitResult(t, end, share));
            }
          } catch (const std::exception&) {
          }
          running.clear();
        }
        return perTest;
      };
      c.firstLineTimeout = perTest;  // the program starts and announces its first test
      const SubprocessResult run = runChild(c);
      const bool ranAny = !finished.empty() || !running.empty();
      std::vector<std::string> left;
      for (const std::string& name : todo)
        if (!finished.count(name) && name != running) left.push_back(name);
      if (!running.empty()) {
        TestResult r;
        r.task = t.id;
        r.kind = "unit";
        r.weight = share;
        r.name = t.id + " " + running;
        r.status = Status::Failed;
        const std::string how = run.timedOut ? "did not finish within " + fmt(perTest) + " s (an endless loop?)"
                                : run.signal ? "stopped the test program: " + run.describe()
                                             : "ended the test program (" + run.describe() + "; a call to exit()?)";
        r.message = t.id + ": " + running + " " + how;
        r.details = "The test program's last output:\n" + tail(run.output, 3000);
        tests.push_back(r);
      } else if (!ranAny || run.succeeded() == false) {
        if (!ranAny) {
          // The program did not get to any test: no point in trying again.
          for (const std::string& name : left) {
            TestResult r = notRun(t, s, t.id + ": the task tests " + run.describe() + " before " + name + " started",
                                  Status::Error);
            r.name = t.id + " " + name;
            r.weight = share;
            r.details = tail(run.output, 3000);
            tests.push_back(r);
          }
          break;
        }
      }
      todo = left;
    }
    return tests;
  }

  static std::string tail(const std::string& text, size_t n) {
    return text.size() > n ? "..." + text.substr(text.size() - n) : text;
  }

  // Renders a reference entry with the student's code (the task isolated); stats from --stats.
  struct Render {
    SubprocessResult run;
    std::string image, stats;
    nlohmann::json statsJson;
  };
  // (byReference: the task too by its reference -- the picture its code must give.)
  Render render(const TaskSpec& t, const std::string& scene, const std::string& technique, const std::string& accel,
                int width, int height, int spp, const nlohmann::json& set, const std::string& stem, double timeout,
                bool byReference = false) {
    Render r;
    r.image = work_ + "/" + stem + ".pfm";
    r.stats = work_ + "/" + stem + ".stats.json";
    fs::remove(r.image);
    fs::remove(r.stats);
    std::vector<std::string> argv = {o_.lightlab, "--quiet", byReference ? "--reference" : "--isolate",
                                     byReference ? std::string("all") : t.id};
    if (o_.threads > 0) argv.insert(argv.end(), {"--threads", std::to_string(o_.threads)});
    argv.insert(argv.end(), {"render", scene, "-t", technique, "-a", accel, "--width", std::to_string(width), "--height",
                             std::to_string(height), "--seed", std::to_string(o_.seed), "-o", r.image, "--stats",
                             r.stats});
    if (spp > 0) argv.insert(argv.end(), {"--spp", std::to_string(spp)});
    for (const auto& [k, v] : set.items()) argv.insert(argv.end(), {"--set", k + "=" + v.get<std::string>()});
    r.run = runChild(child(argv, timeout));
    // Every process of the render is gone: what it wrote can no longer change.
    if (r.run.succeeded()) {
      try {
        r.statsJson = nlohmann::json::parse(readTextFile(r.stats));
      } catch (const std::exception&) {
      }
    }
    return r;
  }

  std::string scenePath(const std::string& s) const {
    if (s.rfind("@build/", 0) == 0) return o_.buildDir + "/data/" + s.substr(7);
    return o_.dataDir + "/" + s;
  }

  // The render's verdict on task t's code: NotImplemented / Failed (a violation) / Passed (go on).
  static Status codeVerdict(const TaskSpec& t, const Render& out, std::string& message) {
    const nlohmann::json missing = objectAt(out.statsJson, "missing_tasks");
    const nlohmann::json violations = objectAt(out.statsJson, "task_violations");
    if (violations.contains(t.id)) {
      message = t.id + ": " + violations.at(t.id).get<std::string>();
      return Status::Failed;
    }
    if (missing.contains(t.id)) {
      message = t.id + " not implemented: " + missing.at(t.id).get<std::string>();
      return Status::NotImplemented;
    }
    return Status::Passed;
  }

  TestResult image(const TaskSpec& t, const TestSpec& s) {
    TestResult r;
    r.task = t.id;
    r.kind = "image";
    r.weight = s.weight;
    const std::string stemName = fs::path(s.reference).stem().string();
    r.name = t.id + " image " + s.reference;
    const auto start = Clock::now();
    const std::string stem = safeName(t.id + "_" + stemName);
    const nlohmann::json& e = s.entry;
    const std::string scene = scenePath(e.at("scene").get<std::string>());
    const int width = e.at("size").at(0).get<int>(), height = e.at("size").at(1).get<int>();
    const Render out = render(t, scene, s.technique, "none", width, height, e.value("spp", 0), e.at("set"), stem,
                              o_.renderTimeout);
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (!out.run.succeeded()) {
      r.status = Status::Error;
      r.message = t.id + ": the render of " + stemName + " " + out.run.describe() + ": " + firstErrorLine(out.run.output);
      r.details = out.run.output;
      return r;
    }
    if (const Status v = codeVerdict(t, out, r.message); v != Status::Passed) {
      r.status = v;
      return r;
    }
    Image student, reference;
    try {
      student = loadImage(out.image);
    } catch (const std::exception& ex) {
      r.status = Status::Error;
      r.message = t.id + ": the render of " + stemName + " wrote no readable image";
      return r;
    }
    reference = loadImage(o_.dataDir + "/references/" + s.reference);
    if (student.width() != reference.width() || student.height() != reference.height()) {
      r.status = Status::Error;
      r.message = t.id + ": the render of " + stemName + " has the wrong size";
      return r;
    }
    const ImageError error = compareImages(student, reference);
    bool ok = true;
    std::string why;
    std::ostringstream details;
    if (e.contains("variance")) {
      // Monte Carlo: the per-pixel Z-test against the reference mean and variance.
      r.kind = "statistical";
      const std::string dir = fs::path(o_.dataDir + "/references/" + s.reference).parent_path().string();
      const Image variance = loadImage(dir + "/" + e.at("variance").get<std::string>());
      const ZTestSettings z = grading::zTestSettings(e);
      const ZTestResult zt = pixelZTest(student, reference, variance, z);
      ok = zt.passed;
      details << "Z-test of " << zt.tests << " pixel channels against the mean of " << e.value("renders", 0)
              << " reference renders: " << zt.rejected << " rejected at the level " << fmt(zt.correctedAlpha)
              << " (alpha " << fmt(z.alpha) << " after Sidak's correction); worst p " << fmt(zt.minPValue)
              << " at pixel " << zt.worstX << "," << zt.worstY << " (z " << fmt(zt.worstZ) << ")\n";
      if (!ok)
        why = std::to_string(zt.rejected) + " pixel channels lie beyond the reference's noise, the worst at pixel " +
              std::to_string(zt.worstX) + "," + std::to_string(zt.worstY) + " (z " + fmt(zt.worstZ) + ")";
      worstPixel(details, t, scene, width, height, s.technique, zt.worstX, zt.worstY, student, reference);
    } else {
      for (const ToleranceCheck& c : checkTolerances(error, e.at("tolerance"))) {
        details << c.metric << " " << fmt(c.value) << (c.isMax ? " (max " : " (min ") << fmt(c.bound) << ")"
                << (c.passed ? "" : " OUT") << "\n";
        if (!c.passed)
          why += (why.empty() ? "" : ", ") + c.metric + " " + fmt(c.value) + (c.isMax ? " > " : " < ") + fmt(c.bound);
        ok = ok && c.passed;
      }
      // Per pixel: |a - b| <= abs + rel |b| in every channel, except for an allowed fraction (edges).
      const nlohmann::json pixels = e.value("pixels", nlohmann::json::object());
      const double absTol = pixels.value("abs", 0.01), relTol = pixels.value("rel", 0.05);
      const double maxFraction = pixels.value("max_fraction", 0.01);
      size_t off = 0, worst = 0;
      double worstExcess = -1.0;
      for (size_t i = 0; i < student.pixels().size(); ++i) {
        bool bad = false;
        for (int c = 0; c < 3; ++c) {
          const double a = static_cast<double>(student.pixels()[i][c]), b = static_cast<double>(reference.pixels()[i][c]);
          const double excess = std::abs(a - b) - (absTol + relTol * std::abs(b));
          if (!(excess <= 0.0)) {
            bad = true;
            if (!(excess <= worstExcess)) {
              worstExcess = std::isfinite(excess) ? excess : 1e30;
              worst = i;
            }
          }
        }
        off += bad ? 1 : 0;
      }
      const double fraction = static_cast<double>(off) / static_cast<double>(student.pixels().size());
      details << "pixels beyond " << fmt(absTol) << " + " << fmt(relTol) << " x |reference|: " << fmt(100.0 * fraction)
              << " % (max " << fmt(100.0 * maxFraction) << " %)\n";
      if (fraction > maxFraction) {
        ok = false;
        why += (why.empty() ? "" : ", ") + fmt(100.0 * fraction) + " % of the pixels differ (max " +
               fmt(100.0 * maxFraction) + " %)";
      }
      if (off > 0)
        worstPixel(details, t, scene, width, height, s.technique, static_cast<int>(worst % static_cast<size_t>(width)),
                   static_cast<int>(worst / static_cast<size_t>(width)), student, reference);
    }
    details << "mean " << fmt(error.meanA) << " (reference " << fmt(error.meanB) << ")\n";
    r.details = details.str();
    r.status = ok ? Status::Passed : Status::Failed;
    if (!ok) r.message = t.id + ": " + stemName + " differs from the reference: " + why;
    // Evidence for the report.
    ImageEvidence ev;
    const std::string base = safeName(t.id + "_" + stemName);
    ev.student = "files/" + base + "_student.png";
    ev.reference = "files/" + base + "_reference.png";
    ev.diff = "files/" + base + "_diff.png";
    float scale = 0.0f;
    saveImage(student, o_.reportDir + "/" + ev.student);
    saveImage(reference, o_.reportDir + "/" + ev.reference);
    const Image heat = differenceHeatmap(student, reference, DiffMode::Absolute, 0.0f, &scale);
    saveImage(withLegend(heat, scale), o_.reportDir + "/" + ev.diff);
    ev.diffScale = static_cast<double>(scale);
    r.images = ev;
    return r;
  }

  // The worst pixel's values and the command that traces it.
  void worstPixel(std::ostringstream& d, const TaskSpec& t, const std::string& scene, int width, int height,
                  const std::string& technique, int x, int y, const Image& student, const Image& reference) const {
    const Rgb a = student.at(x, y), b = reference.at(x, y);
    d << "pixel " << x << "," << y << ": yours (" << fmt(a.r) << ", " << fmt(a.g) << ", " << fmt(a.b)
      << "), the reference (" << fmt(b.r) << ", " << fmt(b.g) << ", " << fmt(b.b) << ")\n";
    std::string rel = scene;
    if (rel.rfind(o_.dataDir, 0) == 0) rel = "data" + rel.substr(o_.dataDir.size());
    d << "trace it: build/lightlab --isolate " << t.id << " trace " << rel << " --pixel " << x << " " << y
      << " --width " << width << " --height " << height << " -t " << technique << " --json\n";
  }

  // Render time of the camera rays on the small and the large scene: one render each, 12 samples per
  // pixel (loading the 235k-triangle mesh and building the structure take far longer than the render,
  // so one longer render measures better than the best of several short ones).
  TestResult complexity(const TaskSpec& t, const TestSpec& s) {
    TestResult r;
    r.task = t.id;
    r.kind = "complexity";
    r.weight = s.weight;
    r.name = t.id + " complexity " + s.accelerator;
    const auto start = Clock::now();
    const nlohmann::json set = {{"intersection", "framework"}, {"light_samples", "1"}};
    const auto best = [&](const std::string& scene, const std::string& tag, double timeout, Render& last) {
      last = render(t, scenePath(scene), "raycast", s.accelerator, 128, 128, 12, set,
                    safeName(t.id + "_complexity_" + s.accelerator + "_" + tag), timeout);
      if (!last.run.succeeded()) return -1.0;
      std::string ignored;
      if (codeVerdict(t, last, ignored) != Status::Passed) return -2.0;
      return number(last.statsJson, "time_seconds", "render", std::numeric_limits<double>::infinity());
    };
    Render small, large;
    const double ts = best(s.small, "small", o_.renderTimeout, small);
    if (ts == -2.0) {
      r.status = codeVerdict(t, small, r.message);
      r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
      return r;
    }
    // Speed means nothing without the right hits: the accelerators return brute force's hits bit for bit,
    // so the picture must be the reference's, pixel for pixel.
    if (ts >= 0.0) {
      const Render ref = render(t, scenePath(s.small), "raycast", s.accelerator, 128, 128, 12, set,
                                safeName(t.id + "_complexity_" + s.accelerator + "_reference"), o_.renderTimeout, true);
      if (ref.run.succeeded()) {
        const Image mine = loadImage(small.image), expected = loadImage(ref.image);
        size_t differ = 0;
        for (size_t i = 0; i < std::min(mine.pixels().size(), expected.pixels().size()); ++i)
          differ += mine.pixels()[i] != expected.pixels()[i] ? 1 : 0;
        if (differ > 0 || mine.pixels().size() != expected.pixels().size()) {
          r.status = Status::Failed;
          r.message = t.id + ": " + s.accelerator + "'s picture of " + s.small + " differs from the reference's in " +
                      std::to_string(differ) + " of " + std::to_string(expected.pixels().size()) +
                      " pixels: the traversal misses or changes hits, so its speed does not count";
          r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
          return r;
        }
      }
    }
    // Far beyond the allowed ratio is a fail: stop waiting there (the process also loads the mesh and
    // builds the structure: a KD-tree over 235k triangles takes seconds).
    const double limit = std::max(60.0, 4.0 * s.maxRatio * std::max(ts, 1e-3));
    const double tl = ts < 0.0 ? -1.0 : best(s.large, "large", limit, large);
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (tl == -2.0) {
      r.status = codeVerdict(t, large, r.message);
      return r;
    }
    const Render& failed = ts < 0.0 ? small : large;
    if (ts < 0.0 || tl < 0.0) {
      if (failed.run.timedOut && ts >= 0.0) {
        r.status = Status::Failed;
        r.message = t.id + ": " + s.accelerator + " on " + s.large + " took over " + fmt(limit) + " s against " +
                    fmt(ts) + " s on " + s.small + ": far worse than logarithmic";
      } else {
        r.status = Status::Error;
        r.message = t.id + ": the " + s.accelerator + " render " + failed.run.describe() + ": " +
                    firstErrorLine(failed.run.output);
        r.details = failed.run.output;
      }
      return r;
    }
    const double ratio = tl / std::max(ts, 1e-6);
    const auto perRay = [](const Render& x) {
      const double rays = number(x.statsJson, "rays", "total", 1.0);
      return number(x.statsJson, "accelerator_stats", "primitives_tested", 0.0) / std::max(rays, 1.0);
    };
    std::ostringstream d;
    d << s.small << ": " << fmt(ts) << " s, " << fmt(perRay(small)) << " primitives tested per ray\n"
      << s.large << ": " << fmt(tl) << " s, " << fmt(perRay(large)) << " primitives tested per ray\n"
      << "time ratio " << fmt(ratio) << " (max " << fmt(s.maxRatio) << ")\n";
    r.details = d.str();
    r.status = ratio <= s.maxRatio ? Status::Passed : Status::Failed;
    if (r.status == Status::Failed)
      r.message = t.id + ": " + s.accelerator + " is " + fmt(ratio) + "x slower on " + s.large + " than on " + s.small +
                  " (max " + fmt(s.maxRatio) + "x): the traversal does not prune";
    return r;
  }

  const GradingSpec& spec_;
  const GraderOptions& o_;
  Clock::time_point start_;
  std::string files_, work_;
  std::vector<std::string> allTests_;
};

}  // namespace

GradeResult grade(const GradingSpec& spec, const GraderOptions& options) { return Grader(spec, options).run(); }

}  // namespace ll::grading
