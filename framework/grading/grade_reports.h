// The grade reports: for the terminal, a self-contained HTML page per
// submission, JUnit XML (for CI servers) and Gradescope's results.json.
// Each writer throws UserError naming the path if it cannot write.
#pragma once

#include <cstdio>
#include <string>

#include "grading/grade_result.h"

namespace ll::grading {

// A table: task, points, status, and under each task that lost points every
// failed check in full (the assertion with its expected and actual values,
// the input that failed and how to trace it), the file and function to look
// at, and at the end `reportPath` (the HTML report), when given.
void writeTextReport(const GradeResult& result, std::FILE* out, bool colour, const std::string& reportPath = "");

// `dir`/report.html: per task its score and tests; per image test the
// student's and the reference image side by side, a wipe slider between
// them and the difference heatmap with its scale, all embedded (base64), so
// the one file can be handed back. Image paths in `result` are relative to `dir`.
void writeHtmlReport(const GradeResult& result, const std::string& dir);

// JUnit XML: one <testsuite> per task, one <testcase> per test; failed and
// not-implemented tests as <failure message=...>, errors as <error>.
void writeJUnitReport(const GradeResult& result, const std::string& path);

// Gradescope's autograder results.json: {"score", "execution_time",
// "output", "tests": [{"name", "number", "score", "max_score", "status", "output"}]},
// one entry per test with its share of the task's points.
void writeGradescopeReport(const GradeResult& result, const std::string& path);

}  // namespace ll::grading
