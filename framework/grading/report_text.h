// Small text helpers shared by the grade report writers.
#pragma once

#include <string>

namespace ll::grading {

// Up to `decimals` decimals without trailing zeros: 73.5, 100, 3.33.
std::string formatNumber(double v, int decimals = 2);

// Escapes & < > " ' for XML and HTML; drops the control characters XML 1.0
// forbids. `text` (element content) keeps line breaks and tabs; otherwise
// (attribute values) they become character references.
std::string escapeMarkup(const std::string& s, bool text = false);

// Writes `text` to `path`; throws UserError "cannot write <path>".
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace ll::grading
