#include "gui/caption_wrap.h"

#include <algorithm>

namespace ll::gui {
namespace {

// `text` split at every occurrence of `sep`, the pieces without it; empty
// pieces (from runs of separators, or at the ends) dropped.
std::vector<std::string> splitAt(std::string_view text, std::string_view sep) {
  std::vector<std::string> pieces;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(sep, start), text.size());
    std::string_view piece = text.substr(start, end - start);
    while (!piece.empty() && piece.front() == ' ') piece.remove_prefix(1);
    while (!piece.empty() && piece.back() == ' ') piece.remove_suffix(1);
    if (!piece.empty()) pieces.emplace_back(piece);
    start = end + sep.size();
  }
  return pieces;
}

// Greedy fill: `pieces` joined by `glue` into lines no wider than `width`
// (a single piece wider than that gets a line of its own).
void fill(const std::vector<std::string>& pieces, const std::string& glue, float width, const TextWidth& measure,
          std::vector<std::string>& out) {
  std::string current;
  for (const std::string& piece : pieces) {
    if (current.empty()) {
      current = piece;
    } else if (measure(current + glue + piece) <= width) {
      current += glue + piece;
    } else {
      out.push_back(current);
      current = piece;
    }
  }
  if (!current.empty()) out.push_back(current);
}

}  // namespace

std::vector<std::string> wrapCaptionLine(const std::string& line, float width, const TextWidth& measure) {
  if (measure(line) <= width) return {line};
  // Fields, with a lone "/" glued to the field after it (a line may start "/  bvh"). A lone "|" only
  // separates: it stays between two fields on one line, and a line break replaces it.
  std::vector<std::string> fields;
  bool glueNext = false;
  for (std::string& f : splitAt(line, "  ")) {
    if (glueNext) fields.back() += "  " + f;
    else fields.push_back(std::move(f));
    glueNext = fields.back() == "/";
  }
  // Fields too wide for a line of their own break at single spaces.
  std::vector<std::string> out;
  std::string current;
  const auto flush = [&] {
    if (!current.empty()) out.push_back(current);
    current.clear();
  };
  bool bar = false;  // a "|" between the line so far and the next field
  for (const std::string& f : fields) {
    if (f == "|") {
      bar = true;
      continue;
    }
    const std::string glue = bar ? "  |  " : "  ";
    bar = false;
    if (measure(f) > width) {
      flush();
      fill(splitAt(f, " "), " ", width, measure, out);
    } else if (current.empty()) {
      current = f;
    } else if (measure(current + glue + f) <= width) {
      current += glue + f;
    } else {
      flush();
      current = f;
    }
  }
  flush();
  if (out.empty()) out.emplace_back();
  return out;
}

}  // namespace ll::gui
