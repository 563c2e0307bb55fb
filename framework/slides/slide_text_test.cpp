// The presenter's text: LaTeX as readable Unicode (scripts, roots, fractions)
// and the line layout that keeps a formula whole where it fits.
#include "slides/slide_text.h"

#include <algorithm>

#include <gtest/gtest.h>

namespace ll {
namespace {

// One unit per character, scripts at 0.7: a stand-in for a monospaced font.
float charWidths(const std::string& text, const TextSpan& span) {
  return static_cast<float>(codePoints(text)) * (span.script != 0 ? 0.7f : 1.0f);
}

// The line's pieces, a space where the layout left a gap between them.
std::string lineText(const LaidLine& line) {
  std::string s;
  float end = 0.0f;
  for (const LaidPiece& p : line.pieces) {
    if (p.x > end + 1e-4f) s += ' ';
    s += p.text;
    end = p.x + p.width;
  }
  return s;
}

TEST(MathText, ScriptsUseUnicodeWhereItExistsElseSmallRuns) {
  EXPECT_EQ(mathAsText("x^2 + F_{ij}"), "x² + Fᵢⱼ");
  EXPECT_EQ(mathAsText("\\sum_{k=1}^{N}"), "∑ₖ₌₁^N");
  EXPECT_EQ(mathAsText("\\mathrm{W\\,m^{-2}\\,sr^{-1}}"), "W m⁻² sr⁻¹");
  const auto runs = mathRuns("L_{local}(p, d)");  // not L_(local)
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[0].text, "L");
  EXPECT_EQ(runs[1].text, "local");
  EXPECT_EQ(runs[1].script, -1);
  EXPECT_EQ(runs[2].text, "(p, d)");
  EXPECT_EQ(runs[2].script, 0);
  const auto up = mathRuns("e^{-\\sigma_a s}");
  ASSERT_EQ(up.size(), 2u);
  EXPECT_EQ(up[1].text, "−σₐ s");
  EXPECT_EQ(up[1].script, 1);
}

TEST(MathText, RootsAndFractionsAreGrouped) {
  EXPECT_EQ(mathAsText("\\sqrt{1 - \\eta^2\\,(1 - \\cos^2\\theta_i)}"), "√(1 − η² (1 − cos²θᵢ))");
  EXPECT_EQ(mathAsText("1/\\sqrt{N}"), "1/√N");
  EXPECT_EQ(mathAsText("\\frac{a}{b}"), "a/b");
  EXPECT_EQ(mathAsText("\\frac{1}{2\\pi}"), "1/(2π)");
  EXPECT_EQ(mathAsText("\\frac{R_s + R_p}{2}"), "(Rₛ + Rₚ)/2");
  EXPECT_EQ(mathAsText("\\frac{l + v}{\\lVert l + v \\rVert}"), "(l + v)/‖l + v‖");
  EXPECT_EQ(mathAsText("\\frac{\\theta}{2}"), "θ/2");
}

TEST(MathText, OperatorsAndSpacing) {
  EXPECT_EQ(mathAsText("\\cos\\theta"), "cos\u2009θ");  // a thin space, as TeX sets it
  EXPECT_EQ(mathAsText("\\max(0, n \\cdot l)"), "max(0, n · l)");
  EXPECT_EQ(mathAsText("\\int_\\Omega L"), "∫_Ω L");
  EXPECT_EQ(mathAsText("B_j \\mathrel{+}= x"), "Bⱼ += x");
  EXPECT_EQ(mathAsText("t_{near} \\le t_{far}"), "tₙₑₐᵣ ≤ t_far");  // no subscript f
  EXPECT_EQ(mathAsText("\\hat L"), "L\u0302");
  EXPECT_EQ(mathAsText("\\begin{cases} a & b \\\\ 0 \\end{cases}"), "{ a\u2003b; 0 }");
}

// TeX's math spacing: the source's spaces are not spacing; \, is one space, \quad an em space.
TEST(MathText, SourceSpacesCollapseAndAQuadIsAnEmSpace) {
  EXPECT_EQ(mathAsText("n_2^2 \\,(1 - F)\\, D(h)"), "n₂² (1 − F) D(h)");
  EXPECT_EQ(mathAsText("\\cos \\theta"), "cos\u2009θ");
  EXPECT_EQ(mathAsText("a, \\quad b \\qquad c"), "a,\u2003b\u2003\u2003c");
  EXPECT_EQ(mathAsText("\\text{with probability } q"), "with probability q");
  EXPECT_EQ(mathAsText("\\pi \\left( (\\alpha^2 - 1) x + 1 \\right)^2"), "π ((α² − 1) x + 1)²");  // none inside brackets
  EXPECT_EQ(mathAsText("\\lvert \\omega_i \\cdot h \\rvert\\, \\lVert n \\rVert"), "|ωᵢ · h| ‖n‖");
  EXPECT_EQ(mathAsText("f(x , y ; z)"), "f(x, y; z)");
}

TEST(SlideText, AFormulaIsOneSpanSetAndScriptsAreTheirOwnSpans) {
  const auto blocks = slideText("the $L_{local}(p)$ term\n");
  ASSERT_EQ(blocks.size(), 1u);
  const auto& spans = blocks[0].spans;
  ASSERT_EQ(spans.size(), 5u);
  EXPECT_EQ(spans[1].text, "L");
  EXPECT_EQ(spans[2].text, "local");
  EXPECT_EQ(spans[2].script, -1);
  EXPECT_EQ(spans[3].text, "(p)");
  EXPECT_EQ(spans[4].text, " term");
}

TEST(SlideText, MathSplitOverLinesIsConvertedWhole) {
  const auto blocks = slideText("a $\\frac{x +\ny}{2}$ b\n");
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].spans[1].text, "(x + y)/2");
}

TEST(WrapSpans, BreaksAtSpacesButNotInsideAFormulaThatFits) {
  const std::vector<TextSpan> spans = {{"so the sum ", SpanStyle::Plain, 0},
                                       {"a + b + c", SpanStyle::Math, 0},
                                       {", then more words", SpanStyle::Plain, 0}};
  const auto lines = wrapSpans(spans, 14.0f, charWidths);
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lineText(lines[0]), "so the sum");
  EXPECT_EQ(lineText(lines[1]), "a + b + c,");  // the comma stays with the formula
  for (const auto& line : lines) {
    EXPECT_LE(line.width, 14.0f);
    EXPECT_EQ(line.scale, 1.0f);
  }
  // The formula's pieces are all on one line.
  int linesWithMath = 0;
  for (const auto& line : lines)
    linesWithMath += std::any_of(line.pieces.begin(), line.pieces.end(), [](const LaidPiece& p) { return p.span == 1; });
  EXPECT_EQ(linesWithMath, 1);
}

TEST(WrapSpans, ScriptRunsStayWithTheirFormula) {
  const std::vector<TextSpan> spans = {{"word ", SpanStyle::Plain, 0}, {"L", SpanStyle::Math, 0},
                                       {"local", SpanStyle::Math, -1}, {"(p, d) + k", SpanStyle::Math, 0},
                                       {"r", SpanStyle::Math, -1}, {" end", SpanStyle::Plain, 0}};
  const auto lines = wrapSpans(spans, 20.0f, charWidths);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lineText(lines[0]), "word");
  EXPECT_EQ(lineText(lines[1]), "Llocal(p, d) + kr end");
  EXPECT_FLOAT_EQ(lines[1].pieces[2].x, 1.0f + 5 * 0.7f);

  // A script never breaks inside, even where its formula must break.
  const std::vector<TextSpan> decay = {{"T = e", SpanStyle::Math, 0}, {"−σₐ s", SpanStyle::Math, 1}};
  const auto narrow = wrapSpans(decay, 3.0f, charWidths);
  ASSERT_EQ(narrow.size(), 2u);
  EXPECT_EQ(lineText(narrow[0]), "T");
  EXPECT_EQ(narrow[1].pieces.back().text, "−σₐ s");
}

TEST(WrapSpans, AnUnbreakableFormulaWiderThanTheColumnIsShrunkOnItsOwnLine) {
  const std::vector<TextSpan> spans = {{"see ", SpanStyle::Plain, 0},
                                       {"0123456789012345678901234567890123456789", SpanStyle::Math, 0},
                                       {" after", SpanStyle::Plain, 0}};
  auto lines = wrapSpans(spans, 30.0f, charWidths);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lineText(lines[0]), "see");
  EXPECT_FLOAT_EQ(lines[1].scale, 0.75f);
  EXPECT_FLOAT_EQ(lines[1].width, 30.0f);
  EXPECT_EQ(lineText(lines[2]), "after");
  lines = wrapSpans(spans, 10.0f, charWidths);  // below the smallest scale: too wide, never broken
  EXPECT_FLOAT_EQ(lines[1].scale, 0.6f);
  EXPECT_FLOAT_EQ(lines[1].width, 24.0f);
  EXPECT_EQ(lines[1].pieces.size(), 1u);
}

// Display math with clauses side by side ("w = ...,  u = ...,  v = w x u", from \quad) breaks at
// those wide gaps on a narrow slide panel, at full size, instead of shrinking the whole line.
TEST(WrapSpans, AFormulaBreaksAtItsWideGapsOutsideBrackets) {
  const std::vector<TextSpan> spans = {{"w = ab,  u = cd,    v = (e,  f)", SpanStyle::Math, 0}};
  auto lines = wrapSpans(spans, 12.0f, charWidths);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lineText(lines[0]), "w = ab,");
  EXPECT_EQ(lineText(lines[1]), "u = cd,");
  EXPECT_EQ(lineText(lines[2]), "v = (e,  f)");  // not inside the brackets
  for (const auto& line : lines) EXPECT_EQ(line.scale, 1.0f);
  lines = wrapSpans(spans, 40.0f, charWidths);  // wide enough: one line, gaps kept
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_FLOAT_EQ(lines[0].width, 31.0f);
}

// A clause wider than the line breaks before its relation, then before an operator, then between
// factors -- the strongest break first, and only where a part does not fit; never after an operator.
TEST(WrapSpans, AFormulaTooWideBreaksBeforeARelationFirst) {
  const std::vector<TextSpan> spans = {{"fₜ(a, b) = (x + y)/z (u + v)/w", SpanStyle::Math, 0}};
  auto lines = wrapSpans(spans, 30.0f, charWidths);  // fits: whole
  ASSERT_EQ(lines.size(), 1u);
  lines = wrapSpans(spans, 28.0f, charWidths);  // a little too wide: shrunk, not broken
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_FLOAT_EQ(lines[0].scale, 28.0f / 30.0f);
  lines = wrapSpans(spans, 22.0f, charWidths);  // broken: "= ..." fits a line of its own
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lineText(lines[0]), "fₜ(a, b)");
  EXPECT_EQ(lineText(lines[1]), "= (x + y)/z (u + v)/w");
  lines = wrapSpans(spans, 14.0f, charWidths);  // "= ..." does not: broken between its factors
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lineText(lines[0]), "fₜ(a, b)");
  EXPECT_EQ(lineText(lines[1]), "= (x + y)/z");
  EXPECT_EQ(lineText(lines[2]), "(u + v)/w");
  for (const auto& line : lines) EXPECT_EQ(line.scale, 1.0f);

  const std::vector<TextSpan> sum = {{"L = a + b·c + d, x", SpanStyle::Math, 0}};
  lines = wrapSpans(sum, 12.0f, charWidths);
  ASSERT_EQ(lines.size(), 2u);
  // Broken before "=" and after the comma first; "= a + b·c + d," is still too wide and breaks before
  // its operators, the parts filling the lines.
  EXPECT_EQ(lineText(lines[0]), "L = a + b·c");
  EXPECT_EQ(lineText(lines[1]), "+ d, x");
}

TEST(WrapSpans, HardBreaksAndPlainWords) {
  const std::vector<TextSpan> spans = {{"one two\nthree four five six", SpanStyle::Plain, 0}};
  const auto lines = wrapSpans(spans, 10.0f, charWidths);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lineText(lines[0]), "one two");  // the hard break
  EXPECT_EQ(lineText(lines[1]), "three four");  // exactly 10 wide
  EXPECT_EQ(lineText(lines[2]), "five six");
  EXPECT_FLOAT_EQ(lines[1].width, 10.0f);  // trailing spaces do not count
}

}  // namespace
}  // namespace ll
