// Text placed in HTML or SVG (XML) markup, in elements or in attributes quoted either way:
// the characters with a meaning there escaped.
#pragma once

#include <string>

namespace ll {

inline std::string escapeMarkup(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else if (c == '\'') out += "&#39;";
    else out += c;
  }
  return out;
}

}  // namespace ll
