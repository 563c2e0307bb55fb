// A slide's Markdown as styled text blocks, for drawing without an HTML
// engine (the GUI's presenter panel), and the line layout that keeps every
// formula whole where it fits. Parsing is md4c's (CommonMark + GitHub tables +
// $...$ math); this file only collects its callbacks. Pure functions: the
// GUI supplies the text widths (wrapSpans' measure), the tests a fake one.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace ll {

enum class SpanStyle { Plain, Strong, Emphasis, Code, Math };

struct TextSpan {
  std::string text;  // UTF-8; math already turned into readable text (mathRuns)
  SpanStyle style = SpanStyle::Plain;
  int script = 0;    // Math only: -1 a subscript, +1 a superscript the GUI draws small, lowered or raised
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

// LaTeX as Unicode text in runs: \rho -> ρ, \int -> ∫, x^2 -> x², F_{ij} ->
// Fᵢⱼ, \sqrt{1 - x} -> √(1 − x), \frac{a}{b} -> a/b ((a + b)/c where the
// parts need grouping), braces dropped. A sub- or superscript with no
// Unicode form (L_{local}) is its own run with script -1 or +1. Spacing as
// in TeX: the source's spaces collapse to one, \, is one space, \quad an em
// space (U+2003). Legible, not typeset.
struct MathRun {
  std::string text;
  int script = 0;  // 0 on the baseline, -1 subscript, +1 superscript
};
std::vector<MathRun> mathRuns(const std::string& latex);
// The runs as one string, scripts without Unicode form as _x, ^x, _(a b).
std::string mathAsText(const std::string& latex);

// Word wrapping of mixed spans into lines at most `width` wide. Breaks at
// spaces; a formula (a run of consecutive Math spans, with the punctuation
// touching it) is glued to its neighbours and breaks inside, outside
// brackets, as display math does: freely at its wide gaps (\quad, \qquad,
// or two spaces, where clauses stand side by side: "w = ...,  u = ..."), and
// only where a part does not fit a line of its own, first before a relation
// (=, ≈, ≤) or after a comma, then before an operator (+, −, ·), then between
// factors (A/B C/D); never after an operator. A part at most 1/0.9 times too
// wide is not broken but drawn a little smaller (scale 0.9 or more) on a line
// of its own; one that cannot break gets a line of its own, drawn at scale
// max(minScale, width / its width); if it is still too wide the line is wider
// than `width` (the caller scrolls).
// A "\n" in the text breaks the line. `measure(text, span)` is the width of
// `text` drawn in that span's style and script at scale 1.
struct LaidPiece {
  size_t span = 0;   // index into the spans
  std::string text;  // a part of spans[span].text
  float x = 0.0f;    // from the line's left edge, at the line's scale
  float width = 0.0f;
};
struct LaidLine {
  std::vector<LaidPiece> pieces;
  float width = 0.0f;  // at `scale`
  float scale = 1.0f;  // < 1 for a formula shrunk to fit
};
using MeasureText = std::function<float(const std::string& text, const TextSpan& span)>;
std::vector<LaidLine> wrapSpans(const std::vector<TextSpan>& spans, float width, const MeasureText& measure,
                                float minScale = 0.6f);

// Characters in UTF-8 text (bytes that do not continue a sequence).
size_t codePoints(const std::string& s);

}  // namespace ll
