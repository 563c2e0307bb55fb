// Small text helpers shared by the grade report writers.
#pragma once

#include <string>

#include "grading/grade_result.h"

namespace ll::grading {

// Up to `decimals` decimals without trailing zeros: 73.5, 100, 3.33.
std::string formatNumber(double v, int decimals = 2);

// Points of the optional (extra credit) tasks: scored, and at most.
struct OptionalPoints {
  double score = 0.0, points = 0.0;
};
OptionalPoints optionalPoints(const GradeResult& result);

// The assignment's points with the optional tasks' apart: "0 / 160 points + 0 / 20 optional", or
// "20 / 20 optional points" when only optional tasks were graded (--task A4.5).
std::string pointsSummary(const GradeResult& result);

// Whether every check of `task` found its stub: the task is still the stub, and
// one line (stubAdvice) says so better than one per check.
bool stillTheStub(const TaskResult& task);
// "still the stub (all 5 checks): write intersectBsp, occludedBsp, then delete the LIGHTLAB_TODO lines"
std::string stubAdvice(const TaskResult& task);

// A check's message as shown under its status: without the "A4.5 not implemented: " that the
// status "not implemented" already says; the name when there is no message.
std::string shownMessage(const TaskResult& task, const TestResult& test);

// Writes `text` to `path`; throws UserError "cannot write <path>".
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace ll::grading
