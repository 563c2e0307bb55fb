// Small text helpers shared by the grade report writers.
#pragma once

#include <string>

namespace ll::grading {

// Up to `decimals` decimals without trailing zeros: 73.5, 100, 3.33.
std::string formatNumber(double v, int decimals = 2);

// Writes `text` to `path`; throws UserError "cannot write <path>".
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace ll::grading
