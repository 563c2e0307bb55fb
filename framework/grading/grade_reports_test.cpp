#include "grading/grade_reports.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/subprocess.h"
#include "grading/grading_spec.h"

namespace ll::grading {
namespace {

namespace fs = std::filesystem;

TestResult test(const std::string& task, Status status, double weight, const std::string& message = "") {
  TestResult t;
  t.task = task;
  t.name = task + " check";
  t.status = status;
  t.weight = weight;
  t.message = message;
  return t;
}

GradeResult sample() {
  GradeResult r;
  r.assignment = "A9";
  r.title = "Sample <&>";
  TaskResult a{"A9.1", "weighted", 30.0, false, 0.0, Status::Error, {}, "", ""};
  a.tests = {test("A9.1", Status::Passed, 2.0), test("A9.1", Status::Failed, 1.0, "A9.1: off by \"one\"")};
  TaskResult b{"A9.2", "stub", 20.0, false, 0.0, Status::Error, {}, "", ""};
  b.tests = {test("A9.2", Status::Passed, 1.0), test("A9.2", Status::NotImplemented, 1.0, "A9.2 not implemented")};
  TaskResult c{"A9.3", "all good", 50.0, false, 0.0, Status::Error, {}, "", ""};
  c.tests = {test("A9.3", Status::Passed, 1.0)};
  r.tasks = {a, b, c};
  finalizeScores(r);
  return r;
}

TEST(GradeResult, ScoresByWeightAndNothingForAStub) {
  const GradeResult r = sample();
  EXPECT_DOUBLE_EQ(r.tasks[0].score, 20.0);  // 30 points * 2/3 of the weight passed
  EXPECT_EQ(r.tasks[0].status, Status::Failed);
  EXPECT_DOUBLE_EQ(r.tasks[1].score, 0.0);  // a stub ran: its passed test earns nothing
  EXPECT_EQ(r.tasks[1].status, Status::NotImplemented);
  EXPECT_EQ(r.tasks[2].status, Status::Passed);
  EXPECT_DOUBLE_EQ(r.score, 70.0);
  EXPECT_DOUBLE_EQ(r.maxScore, 100.0);
}

TEST(GradeReports, GradescopeJUnitAndHtmlAgreeWithTheScores) {
  const GradeResult r = sample();
  const fs::path dir = fs::temp_directory_path() / "lightlab_grade_reports_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  writeGradescopeReport(r, (dir / "results.json").string());
  const nlohmann::json g = nlohmann::json::parse(readTextFile((dir / "results.json").string()));
  EXPECT_DOUBLE_EQ(g.at("score").get<double>(), 70.0);
  double sum = 0.0, best = 0.0;
  for (const auto& t : g.at("tests")) {
    sum += t.at("score").get<double>();
    best += t.at("max_score").get<double>();
    if (t.at("number") == "A9.2") {
      EXPECT_EQ(t.at("score").get<double>(), 0.0);
    }
  }
  EXPECT_NEAR(sum, 70.0, 1e-3);
  EXPECT_NEAR(best, 100.0, 1e-3);

  writeJUnitReport(r, (dir / "junit.xml").string());
  const std::string xml = readTextFile((dir / "junit.xml").string());
  EXPECT_NE(xml.find("<testsuites"), std::string::npos);
  EXPECT_NE(xml.find("off by &quot;one&quot;"), std::string::npos);  // escaped
  EXPECT_NE(xml.find("type=\"not implemented\""), std::string::npos);
  EXPECT_EQ(xml.find("\"one\""), std::string::npos);

  writeHtmlReport(r, dir.string());
  const std::string html = readTextFile((dir / "report.html").string());
  EXPECT_NE(html.find("70 / 100"), std::string::npos);
  EXPECT_NE(html.find("Sample &lt;&amp;&gt;"), std::string::npos);
  // A missing folder is made; one that cannot be (below a file) is an error naming the path.
  writeJUnitReport(r, (dir / "missing" / "junit.xml").string());
  EXPECT_TRUE(fs::exists(dir / "missing" / "junit.xml"));
  EXPECT_THROW(writeJUnitReport(r, (dir / "report.html" / "junit.xml").string()), UserError);
  fs::remove_all(dir);
}

std::string textReport(const GradeResult& r) {
  char* buffer = nullptr;
  size_t size = 0;
  std::FILE* f = open_memstream(&buffer, &size);
  writeTextReport(r, f, false, "");
  std::fclose(f);
  std::string text(buffer, size);
  std::free(buffer);
  return text;
}

// What a student reads first: a task that is still the stub takes one line, not
// one per check; a partly written one names each check its stub ran in, once;
// optional points are shown apart from the assignment's.
TEST(GradeReports, TheTextReportSaysAStubOnceAndShowsOptionalPointsApart) {
  GradeResult r;
  r.assignment = "A9";
  r.title = "Sample";
  TaskResult stub{"A9.1", "stub", 40.0, false, 0.0, Status::Error, {}, "a9/stub.cpp", "f, g"};
  stub.tests = {test("A9.1", Status::NotImplemented, 1.0, "A9.1 not implemented: its stub ran in T.One"),
                test("A9.1", Status::NotImplemented, 1.0, "A9.1 not implemented: its stub ran in T.Two"),
                test("A9.1", Status::NotImplemented, 1.0,
                     "A9.1 not implemented: complexity check not run, the stub ran in an earlier one")};
  TaskResult half{"A9.2", "half", 60.0, false, 0.0, Status::Error, {}, "a9/half.cpp", "h"};
  half.tests = {test("A9.2", Status::Passed, 1.0),
                test("A9.2", Status::NotImplemented, 1.0, "A9.2 not implemented: its stub ran in T.Three")};
  TaskResult extra{"A9.3", "extra", 20.0, true, 0.0, Status::Error, {}, "a9/extra.cpp", "k"};
  extra.tests = {test("A9.3", Status::Passed, 1.0)};
  r.tasks = {stub, half, extra};
  finalizeScores(r);
  const std::string text = textReport(r);
  EXPECT_NE(text.find("A9 Sample: 0 / 100 points + 20 / 20 optional (seed"), std::string::npos) << text;
  EXPECT_NE(text.find("  not implemented  still the stub (all 3 checks): write f, g, then delete the LIGHTLAB_TODO "
                      "lines\n"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("T.One"), std::string::npos) << text;
  EXPECT_NE(text.find("  not implemented its stub ran in T.Three\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("not implemented A9.2 not implemented"), std::string::npos) << text;

  // The HTML report says the same: one card for the stub, the file to open, optional points apart.
  const fs::path dir = fs::temp_directory_path() / "lightlab_grade_text_test";
  fs::remove_all(dir);
  writeHtmlReport(r, dir.string());
  const std::string html = readTextFile((dir / "report.html").string());
  fs::remove_all(dir);
  EXPECT_NE(html.find("0 / 100 points + 20 / 20 optional"), std::string::npos);
  EXPECT_NE(html.find("still the stub (all 3 checks): write f, g"), std::string::npos);
  EXPECT_NE(html.find("look at: <code>a9/stub.cpp</code> (f, g)"), std::string::npos);
  EXPECT_NE(html.find("Optional, on top</td><td class=\"score\">20 / 20"), std::string::npos);
  EXPECT_EQ(html.find("its stub ran in T.One"), std::string::npos);  // no card per check of a stub
  EXPECT_NE(html.find("its stub ran in T.Three"), std::string::npos);

  r.tasks = {extra};  // only the optional task graded (--task A9.3)
  finalizeScores(r);
  EXPECT_NE(textReport(r).find("A9 Sample: 20 / 20 optional points (seed"), std::string::npos) << textReport(r);
}

TEST(GradingSpec, EveryAssignmentsSpecLoadsWithItsReferences) {
  const std::string root = std::string(LIGHTLAB_DATA_DIR) + "/..";
  const std::vector<std::string> specs = findGradingSpecs(root + "/assignments");
  ASSERT_GE(specs.size(), 5u);
  for (const std::string& path : specs) {
    const GradingSpec s = loadGradingSpec(path, std::string(LIGHTLAB_DATA_DIR));
    SCOPED_TRACE(path);
    double points = 0.0;
    for (const TaskSpec& t : s.tasks) {
      points += t.points;
      EXPECT_FALSE(t.tests.empty());
      for (const TestSpec& k : t.tests)
        if (k.kind == "image") {
          EXPECT_TRUE(k.entry.contains("scene"));
        }
    }
    EXPECT_GT(points, 0.0);
    for (const std::string& f : s.studentFiles()) EXPECT_TRUE(fs::exists(fs::path(path).parent_path() / f)) << f;
  }
  EXPECT_EQ(findGradingSpec("a2", root + "/assignments", LIGHTLAB_DATA_DIR).assignment, "A2");
  EXPECT_THROW(findGradingSpec("A0", root + "/assignments", LIGHTLAB_DATA_DIR), UserError);
}

}  // namespace
}  // namespace ll::grading
