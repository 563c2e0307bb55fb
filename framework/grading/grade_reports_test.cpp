#include "grading/grade_reports.h"

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
