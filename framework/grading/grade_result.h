// What `lightlab grade` found: one GradeResult per assignment, a TaskResult
// per task ID (A2.4) with its points, and a TestResult per check. The report
// writers (grade_reports.h) turn it into text, HTML, JUnit XML and
// Gradescope's results.json.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace ll::grading {

enum class Status {
  Passed,
  Failed,          // ran and gave a wrong answer
  NotImplemented,  // the task's stub ran ("A2.4 not implemented")
  Error,           // crashed, timed out, or could not run
};

// How each status is shown: its name ("passed", "failed", "not implemented",
// "error"), the HTML report's CSS class and the terminal's ANSI colour.
struct StatusStyle {
  const char* name;
  const char* cssClass;
  const char* ansiColour;
};
const StatusStyle& statusStyle(Status s);
inline const char* statusName(Status s) { return statusStyle(s).name; }

// Images of an image test, as PNG files (sRGB, for people) inside the report
// folder; paths relative to that folder. Empty when not written.
struct ImageEvidence {
  std::string student;    // the student's render
  std::string reference;  // the solution's
  std::string diff;       // difference heatmap (inferno) with its legend strip
  double diffScale = 0.0; // the error value at the legend's right end (linear radiance)
};

struct TestResult {
  std::string name;     // unique within the assignment, starts with the task ID: "A2.4 image sphere_point_light"
  std::string task;     // the task this test grades: "A2.4"
  std::string kind;     // "unit", "image", "statistical", "complexity"
  Status status = Status::Error;
  double weight = 1.0;  // share of the task's points (relative to the task's other tests)
  std::string message;  // one line naming the task and what differs; empty when passed
  std::string details;  // the whole story: every failed assertion with expected and actual values, measured
                        // values, the input that failed and how to trace it; several lines
  double seconds = 0.0; // wall time of the check
  std::optional<ImageEvidence> images;
};

struct TaskResult {
  std::string id;     // "A2.4"
  std::string title;  // "Blinn-Phong shading"
  double points = 0.0;  // maximum
  bool optional = false;  // extra credit: not part of GradeResult::maxScore
  double score = 0.0;   // points * (weight of the passed tests / weight of all tests)
  Status status = Status::Error;  // Passed only if every test passed; NotImplemented if any test found the stub
  std::vector<TestResult> tests;
  std::string file;       // the student's file to look at: "assignments/a2_raycasting/blinn_phong.cpp"
  std::string functions;  // what it defines: "blinnPhong"
};

struct GradeResult {
  std::string assignment;  // "A2"
  std::string title;       // "Ray casting"
  std::vector<TaskResult> tasks;
  double score = 0.0;
  double maxScore = 0.0;
  double seconds = 0.0;  // wall time of the whole grading
  unsigned seed = 0;     // passed to every render
  int threads = 0;       // 0 = all cores
};

// Sums scores and sets each task's status from its tests (call after filling the tests).
void finalizeScores(GradeResult& result);

}  // namespace ll::grading
