#include "grading/grader.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <regex>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/image.h"
#include "core/progress.h"
#include "core/subprocess.h"
#include "grading/tolerance.h"
#include "metrics/image_metrics.h"
#include "metrics/pixel_ztest.h"

namespace ll::grading {

namespace fs = std::filesystem;

namespace {

std::string fmt(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.3g", v);
  return buffer;
}

// The first line of a file, for "why did it fail".
std::string firstLine(const std::string& path) {
  const std::string text = readTextFile(path);
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (line.find("error") != std::string::npos) return line;
  return text.substr(0, text.find('\n'));
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

// Common arguments of every lightlab child.
std::vector<std::string> lightlabArgs(const GraderOptions& o) {
  std::vector<std::string> a = {o.lightlab, "--quiet"};
  if (o.threads > 0) a.insert(a.end(), {"--threads", std::to_string(o.threads)});
  return a;
}

// Task IDs named "<id> not implemented" in `text`, with what follows.
std::map<std::string, std::string> notImplementedIn(const std::string& text) {
  static const std::regex pattern(R"((A\d+\.\d+) not implemented:?\s*([^\n"]*))");
  std::map<std::string, std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), pattern); it != std::sregex_iterator(); ++it)
    out.emplace((*it)[1].str(), (*it)[2].str());
  return out;
}

class Grader {
 public:
  Grader(const GradingSpec& spec, const GraderOptions& o) : spec_(spec), o_(o) {
    files_ = o.reportDir + "/files";
    fs::create_directories(files_);
  }

  GradeResult run() {
    const auto start = std::chrono::steady_clock::now();
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
    ProgressBar progress("grading " + spec_.assignment, static_cast<double>(total), o_.quiet);
    size_t done = 0;
    for (const TaskSpec& t : spec_.tasks) {
      if (!o_.onlyTask.empty() && t.id != o_.onlyTask) continue;
      TaskResult task;
      task.id = t.id;
      task.title = t.title;
      task.points = t.points;
      for (const TestSpec& s : t.tests) {
        std::vector<TestResult> tests;
        if (s.kind == "unit") tests = unit(t, s);
        else if (s.kind == "image") tests = {image(t, s)};
        else tests = {complexity(t, s)};
        for (TestResult& r : tests) task.tests.push_back(std::move(r));
        progress.update(static_cast<double>(++done));
      }
      result.tasks.push_back(std::move(task));
    }
    progress.finish();
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    finalizeScores(result);
    return result;
  }

 private:
  // The task's gtest cases, each one test sharing the spec's weight.
  std::vector<TestResult> unit(const TaskSpec& t, const TestSpec& s) {
    const std::string stem = files_ + "/" + safeName(t.id + "_" + s.filter);
    const std::string json = stem + ".json", out = stem + ".out.txt", stubs = stem + ".stubs.jsonl";
    fs::remove(json);
    fs::remove(stubs);
    const SubprocessResult run =
        runSubprocess({o_.taskTests, "--gtest_filter=" + s.filter, "--gtest_output=json:" + json,
                       "--gtest_brief=1"},
                      out, out, o_.unitTimeout, {"LIGHTLAB_TASK_REPORT=" + stubs});
    // The stubs each test ran (tests/task_tests_main.cpp).
    std::map<std::string, std::set<std::string>> stubsRun;
    {
      std::istringstream lines(readTextFile(stubs));
      std::string line;
      while (std::getline(lines, line)) {
        try {
          const nlohmann::json j = nlohmann::json::parse(line);
          stubsRun[j.at("test").get<std::string>()] = j.at("stubs").get<std::set<std::string>>();
        } catch (const std::exception&) {
        }
      }
    }
    std::vector<TestResult> tests;
    if (run.succeeded() || (run.started && !run.timedOut && run.signal == 0 && run.exitCode == 1 && fs::exists(json))) {
      nlohmann::json report;
      try {
        report = nlohmann::json::parse(readTextFile(json));
      } catch (const std::exception&) {
      }
      for (const auto& suite : report.value("testsuites", nlohmann::json::array()))
        for (const auto& c : suite.value("testsuite", nlohmann::json::array())) {
          TestResult r;
          r.task = t.id;
          r.kind = "unit";
          r.name = t.id + " " + c.value("classname", "") + "." + c.value("name", "");
          const std::string time = c.value("time", "0s");
          r.seconds = std::atof(time.c_str());
          std::string failures;
          for (const auto& f : c.value("failures", nlohmann::json::array())) failures += f.value("failure", "") + "\n";
          if (c.value("result", "") == "SKIPPED") continue;
          auto missing = notImplementedIn(failures);
          for (const std::string& id : stubsRun[c.value("classname", "") + "." + c.value("name", "")])
            missing.emplace(id, "its stub ran in this test");
          if (missing.count(t.id)) {
            r.status = Status::NotImplemented;
            r.message = t.id + " not implemented: " + missing.at(t.id);
          } else if (failures.empty()) {
            r.status = Status::Passed;
          } else {
            r.status = Status::Failed;
            const std::string first = failures.substr(0, failures.find('\n', failures.find('\n') + 1));
            r.message = t.id + ": " + c.value("name", "") + " failed: " + oneLine(first);
            for (const auto& [id, what] : missing) r.message += " (" + id + " not implemented: its stand-in ran)";
          }
          r.details = failures;
          tests.push_back(std::move(r));
        }
      if (tests.empty()) {
        TestResult r = failedRun(t, "unit " + s.filter, "no task tests match '" + s.filter + "'", out);
        tests.push_back(r);
      }
    } else {
      // Crashed or timed out: name the test that was running.
      const std::string text = readTextFile(out);
      std::string running;
      const auto at = text.rfind("[ RUN      ] ");
      if (at != std::string::npos) running = text.substr(at + 13, text.find('\n', at) - at - 13);
      tests.push_back(failedRun(t, "unit " + s.filter,
                                "the task tests " + run.describe() + (running.empty() ? "" : " in " + running), out));
    }
    const double share = s.weight / static_cast<double>(tests.size());
    for (TestResult& r : tests) r.weight = share;
    return tests;
  }

  TestResult failedRun(const TaskSpec& t, const std::string& name, const std::string& why, const std::string& log) {
    TestResult r;
    r.task = t.id;
    r.kind = "unit";
    r.name = t.id + " " + name;
    r.status = Status::Error;
    r.message = t.id + ": " + why;
    const std::string text = readTextFile(log);
    r.details = text.size() > 4000 ? text.substr(text.size() - 4000) : text;
    return r;
  }

  // Renders a reference entry with the student's code; missing tasks from --stats.
  struct Render {
    SubprocessResult run;
    std::string image, stats, log;
    nlohmann::json statsJson;
  };
  Render render(const std::string& scene, const std::string& technique, const std::string& accel, int width,
                int height, int spp, const nlohmann::json& set, const std::string& stem, double timeout) {
    Render r;
    r.image = stem + ".pfm";
    r.stats = stem + ".stats.json";
    r.log = stem + ".log.txt";
    fs::remove(r.stats);
    std::vector<std::string> argv = lightlabArgs(o_);
    argv.insert(argv.end(), {"render", scene, "-t", technique, "-a", accel, "--width", std::to_string(width), "--height",
                             std::to_string(height), "--seed", std::to_string(o_.seed), "-o", r.image, "--stats",
                             r.stats});
    if (spp > 0) argv.insert(argv.end(), {"--spp", std::to_string(spp)});
    for (const auto& [k, v] : set.items()) argv.insert(argv.end(), {"--set", k + "=" + v.get<std::string>()});
    r.run = runSubprocess(argv, r.log, r.log, timeout);
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

  TestResult image(const TaskSpec& t, const TestSpec& s) {
    TestResult r;
    r.task = t.id;
    r.kind = "image";
    r.weight = s.weight;
    const std::string stemName = fs::path(s.reference).stem().string();
    r.name = t.id + " image " + s.reference;
    const auto start = std::chrono::steady_clock::now();
    const std::string stem = files_ + "/" + safeName(t.id + "_" + stemName);
    const nlohmann::json& e = s.entry;
    const Render out = render(scenePath(e.at("scene").get<std::string>()), s.technique, "none",
                              e.at("size").at(0).get<int>(), e.at("size").at(1).get<int>(), e.value("spp", 0),
                              e.at("set"), stem,
                              o_.renderTimeout);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!out.run.succeeded()) {
      r.status = Status::Error;
      r.message = t.id + ": the render of " + stemName + " " + out.run.describe() + ": " + firstLine(out.log);
      r.details = readTextFile(out.log);
      return r;
    }
    const nlohmann::json missing = out.statsJson.is_object()
                                       ? out.statsJson.value("missing_tasks", nlohmann::json::object())
                                       : nlohmann::json::object();
    std::string alsoMissing;
    for (const auto& [id, what] : missing.items())
      if (id != t.id) alsoMissing += " (" + id + " not implemented: its stand-in ran)";
    if (missing.contains(t.id)) {
      r.status = Status::NotImplemented;
      r.message = t.id + " not implemented: " + missing.at(t.id).get<std::string>();
      return r;
    }
    const Image student = loadImage(out.image);
    const Image reference = loadImage(o_.dataDir + "/references/" + s.reference);
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
              << " (alpha " << fmt(z.alpha) << " after Sidak's correction); worst p " << fmt(zt.minPValue) << " at "
              << zt.worstX << "," << zt.worstY << " (z " << fmt(zt.worstZ) << ")\n";
      if (!ok)
        why = std::to_string(zt.rejected) + " pixel channels lie beyond the reference's noise (worst z " +
              fmt(zt.worstZ) + " at " + std::to_string(zt.worstX) + "," + std::to_string(zt.worstY) + ")";
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
    size_t off = 0;
    for (size_t i = 0; i < student.pixels().size(); ++i)
      for (int c = 0; c < 3; ++c) {
        const double a = static_cast<double>(student.pixels()[i][c]), b = static_cast<double>(reference.pixels()[i][c]);
        if (!(std::abs(a - b) <= absTol + relTol * std::abs(b))) {
          ++off;
          break;
        }
      }
    const double fraction = static_cast<double>(off) / static_cast<double>(student.pixels().size());
    details << "pixels beyond " << fmt(absTol) << " + " << fmt(relTol) << "|ref|: " << fmt(100.0 * fraction) << " % (max "
            << fmt(100.0 * maxFraction) << " %)\n";
    if (fraction > maxFraction) {
      ok = false;
      why += (why.empty() ? "" : ", ") + fmt(100.0 * fraction) + " % of the pixels differ (max " +
             fmt(100.0 * maxFraction) + " %)";
    }
    }
    details << "mean " << fmt(error.meanA) << " (reference " << fmt(error.meanB) << ")\n";
    r.details = details.str();
    r.status = ok ? Status::Passed : Status::Failed;
    if (!ok) {
      std::string uses;
      for (const auto& id : e.value("tasks", std::vector<std::string>()))
        if (id != t.id) uses += (uses.empty() ? "" : ", ") + id;
      r.message = t.id + ": " + stemName + " differs from the reference: " + why +
                  (uses.empty() ? "" : "; the picture also uses " + uses) + alsoMissing;
    }
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

  // Render time of the camera rays on the small and the large scene; the best of three.
  TestResult complexity(const TaskSpec& t, const TestSpec& s) {
    TestResult r;
    r.task = t.id;
    r.kind = "complexity";
    r.weight = s.weight;
    r.name = t.id + " complexity " + s.accelerator;
    const auto start = std::chrono::steady_clock::now();
    const nlohmann::json set = {{"intersection", "framework"}, {"light_samples", "1"}};
    const auto best = [&](const std::string& scene, const std::string& tag, double timeout, Render& last) {
      double seconds = std::numeric_limits<double>::infinity();
      for (int k = 0; k < 3; ++k) {
        last = render(scenePath(scene), "raycast", s.accelerator, 128, 128, 4, set,
                      files_ + "/" + safeName(t.id + "_complexity_" + s.accelerator + "_" + tag), timeout);
        if (!last.run.succeeded()) return -1.0;
        seconds = std::min(seconds, number(last.statsJson, "time_seconds", "render", std::numeric_limits<double>::infinity()));
      }
      return seconds;
    };
    Render small, large;
    const double ts = best(s.small, "small", o_.renderTimeout, small);
    const auto stubRan = [&](const Render& x) {
      return x.statsJson.is_object() && x.statsJson.contains("missing_tasks") &&
             x.statsJson.at("missing_tasks").contains(t.id);
    };
    if (ts >= 0.0 && stubRan(small)) {  // the stub (brute force) ran: no need to time it on the large mesh
      r.status = Status::NotImplemented;
      r.message = t.id + " not implemented: " + small.statsJson.at("missing_tasks").at(t.id).get<std::string>();
      r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return r;
    }
    // Far beyond the allowed ratio is a fail: stop waiting there (the process also loads the mesh and
    // builds the structure: a KD-tree over 235k triangles takes seconds).
    const double limit = std::max(60.0, 4.0 * s.maxRatio * std::max(ts, 1e-3));
    const double tl = ts < 0.0 ? -1.0 : best(s.large, "large", limit, large);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const Render& failed = ts < 0.0 ? small : large;
    if (ts < 0.0 || tl < 0.0) {
      if (failed.run.timedOut && ts >= 0.0) {
        r.status = Status::Failed;
        r.message = t.id + ": " + s.accelerator + " on " + s.large + " took over " + fmt(limit) + " s against " +
                    fmt(ts) + " s on " + s.small + ": far worse than logarithmic";
      } else {
        r.status = Status::Error;
        r.message = t.id + ": the " + s.accelerator + " render " + failed.run.describe() + ": " + firstLine(failed.log);
      }
    } else {
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
        r.message = t.id + ": " + s.accelerator + " is " + fmt(ratio) + "x slower on " + s.large + " than on " +
                    s.small + " (max " + fmt(s.maxRatio) + "x): the traversal does not prune";
    }
    const nlohmann::json& stats = (ts < 0.0 ? small : large).statsJson;
    const nlohmann::json missing =
        stats.is_object() ? stats.value("missing_tasks", nlohmann::json::object()) : nlohmann::json::object();
    if (missing.contains(t.id)) {
      r.status = Status::NotImplemented;
      r.message = t.id + " not implemented: " + missing.at(t.id).get<std::string>();
    } else if (r.status != Status::Passed) {
      for (const auto& [id, what] : missing.items()) r.message += " (" + id + " not implemented: its stand-in ran)";
    }
    return r;
  }

  static std::string oneLine(std::string s) {
    std::replace(s.begin(), s.end(), '\n', ' ');
    if (s.size() > 300) s = s.substr(0, 300) + "...";
    return s;
  }

  const GradingSpec& spec_;
  const GraderOptions& o_;
  std::string files_;
};

}  // namespace

GradeResult grade(const GradingSpec& spec, const GraderOptions& options) { return Grader(spec, options).run(); }

}  // namespace ll::grading
