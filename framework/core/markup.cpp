#include "core/markup.h"

#include "core/utf8.h"

namespace ll {

std::string escapeMarkup(const std::string& raw, bool text) {
  const std::string s = replaceInvalidUtf8(raw);
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      case '\n': out += text ? "\n" : "&#10;"; break;
      case '\r': out += "&#13;"; break;
      case '\t': out += text ? "\t" : "&#9;"; break;
      default:
        if (static_cast<unsigned char>(c) >= 0x20) out += c;  // other controls are not allowed in XML 1.0
    }
  }
  return out;
}

}  // namespace ll
