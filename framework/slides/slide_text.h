// A slide's Markdown as styled text blocks, for drawing without an HTML
// engine (the GUI's presenter panel). Parsing is md4c's (CommonMark + GitHub
// tables + $...$ math); this file only collects its callbacks.
#pragma once

#include <string>
#include <vector>

namespace ll {

enum class SpanStyle { Plain, Strong, Emphasis, Code, Math };

struct TextSpan {
  std::string text;  // UTF-8; math already turned into readable text (mathAsText)
  SpanStyle style = SpanStyle::Plain;
};

enum class BlockKind {
  Heading,      // level = 1..6
  Paragraph,
  ListItem,     // level = nesting depth (1 = top); marker = "•" or "3."
  Code,         // a fenced or indented code block, one span with newlines
  DisplayMath,  // $$...$$ on its own line
  TableRow,     // cells separated by "  |  "; level 1 for the header row
  Figure,       // where the slide's preset block stood
};

struct TextBlock {
  BlockKind kind = BlockKind::Paragraph;
  int level = 0;
  std::string marker;
  std::vector<TextSpan> spans;
};

std::vector<TextBlock> slideText(const std::string& markdown);

// LaTeX as plain Unicode text: \rho -> ρ, \int -> ∫, x^2 -> x², \frac{a}{b}
// -> (a)/(b), braces dropped. Legible, not typeset.
std::string mathAsText(const std::string& latex);

}  // namespace ll
