#include "slides/slide_text.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstring>
#include <map>
#include <set>
#include <string_view>

#include <md4c.h>

#include "slides/deck.h"

namespace ll {

namespace {

struct Collector {
  std::vector<TextBlock> blocks;
  std::vector<int> lists;       // per open list: next number, or -1 for bullets
  std::vector<SpanStyle> styles;  // open spans
  int paragraphLevel = 0;  // list depth of the paragraph a display equation interrupted
  std::string math;        // the LaTeX of the open math span, converted when it closes

  TextBlock& open(BlockKind kind, int level = 0, std::string marker = "") {
    blocks.push_back({kind, level, std::move(marker), {}});
    return blocks.back();
  }
  SpanStyle style() const { return styles.empty() ? SpanStyle::Plain : styles.back(); }
  void add(const std::string& text, SpanStyle s, int script = 0) {
    if (text.empty()) return;
    if (blocks.empty()) open(BlockKind::Paragraph);
    auto& spans = blocks.back().spans;
    if (!spans.empty() && spans.back().style == s && spans.back().script == script)
      spans.back().text += text;
    else
      spans.push_back({text, s, script});
  }
  void closeMath() {
    for (const MathRun& r : mathRuns(math)) add(r.text, SpanStyle::Math, r.script);
    math.clear();
  }
};

int enterBlock(MD_BLOCKTYPE type, void* detail, void* user) {
  auto& c = *static_cast<Collector*>(user);
  switch (type) {
    case MD_BLOCK_H:
      c.open(BlockKind::Heading, static_cast<int>(static_cast<MD_BLOCK_H_DETAIL*>(detail)->level));
      break;
    case MD_BLOCK_P:  // a loose list item's first paragraph stays in the item
      if (c.blocks.empty() || c.blocks.back().kind != BlockKind::ListItem || !c.blocks.back().spans.empty())
        c.open(BlockKind::Paragraph, static_cast<int>(c.lists.size()));
      break;
    case MD_BLOCK_UL:
      c.lists.push_back(-1);
      break;
    case MD_BLOCK_OL:
      c.lists.push_back(static_cast<int>(static_cast<MD_BLOCK_OL_DETAIL*>(detail)->start));
      break;
    case MD_BLOCK_LI: {
      int& n = c.lists.back();
      c.open(BlockKind::ListItem, static_cast<int>(c.lists.size()), n < 0 ? "\xE2\x80\xA2" : std::to_string(n++) + ".");
      break;
    }
    case MD_BLOCK_CODE:
      c.open(BlockKind::Code);
      break;
    case MD_BLOCK_TR:
      c.open(BlockKind::TableRow);
      break;
    case MD_BLOCK_TH:
    case MD_BLOCK_TD:
      if (!c.blocks.back().spans.empty()) c.add("  |  ", SpanStyle::Plain);
      if (type == MD_BLOCK_TH) c.blocks.back().level = 1;
      break;
    default:
      break;
  }
  return 0;
}

int leaveBlock(MD_BLOCKTYPE type, void*, void* user) {
  auto& c = *static_cast<Collector*>(user);
  if (type == MD_BLOCK_UL || type == MD_BLOCK_OL) c.lists.pop_back();
  return 0;
}

int enterSpan(MD_SPANTYPE type, void*, void* user) {
  auto& c = *static_cast<Collector*>(user);
  switch (type) {
    case MD_SPAN_STRONG:
      c.styles.push_back(SpanStyle::Strong);
      break;
    case MD_SPAN_EM:
      c.styles.push_back(SpanStyle::Emphasis);
      break;
    case MD_SPAN_CODE:
      c.styles.push_back(SpanStyle::Code);
      break;
    case MD_SPAN_LATEXMATH:
      c.styles.push_back(SpanStyle::Math);
      break;
    case MD_SPAN_LATEXMATH_DISPLAY: {  // its own line; the paragraph goes on after it
      c.paragraphLevel = static_cast<int>(c.lists.size());
      c.open(BlockKind::DisplayMath);
      c.styles.push_back(SpanStyle::Math);
      break;
    }
    default:
      c.styles.push_back(c.style());
      break;
  }
  return 0;
}

int leaveSpan(MD_SPANTYPE type, void*, void* user) {
  auto& c = *static_cast<Collector*>(user);
  c.styles.pop_back();
  if (type == MD_SPAN_LATEXMATH || type == MD_SPAN_LATEXMATH_DISPLAY) c.closeMath();
  if (type == MD_SPAN_LATEXMATH_DISPLAY) c.open(BlockKind::Paragraph, c.paragraphLevel);
  return 0;
}

int text(MD_TEXTTYPE type, const MD_CHAR* data, MD_SIZE size, void* user) {
  auto& c = *static_cast<Collector*>(user);
  const std::string s(data, size);
  switch (type) {
    case MD_TEXT_SOFTBR:
      if (c.style() == SpanStyle::Math)
        c.math += ' ';
      else
        c.add(" ", c.style());
      break;
    case MD_TEXT_BR:
      c.add("\n", c.style());
      break;
    case MD_TEXT_LATEXMATH:
      c.math += s;
      break;
    case MD_TEXT_HTML:
      if (s.find(kFigureMarker) != std::string::npos) c.open(BlockKind::Figure);
      break;
    case MD_TEXT_ENTITY:
      c.add(s == "&amp;" ? "&" : s == "&lt;" ? "<" : s == "&gt;" ? ">" : s == "&nbsp;" ? " " : s, c.style());
      break;
    case MD_TEXT_CODE:
      c.add(s, SpanStyle::Code);
      break;
    default:
      c.add(s, c.style());
      break;
  }
  return 0;
}

const std::map<std::string, std::string>& symbols() {
  static const std::map<std::string, std::string> table = {
      {"alpha", "α"}, {"beta", "β"}, {"gamma", "γ"}, {"delta", "δ"}, {"epsilon", "ε"}, {"varepsilon", "ε"},
      {"eta", "η"}, {"theta", "θ"}, {"lambda", "λ"}, {"mu", "μ"}, {"pi", "π"}, {"rho", "ρ"}, {"sigma", "σ"},
      {"tau", "τ"}, {"phi", "φ"}, {"varphi", "φ"}, {"omega", "ω"}, {"xi", "ξ"}, {"kappa", "κ"}, {"nu", "ν"},
      {"Gamma", "Γ"}, {"Delta", "Δ"}, {"Theta", "Θ"}, {"Lambda", "Λ"}, {"Pi", "Π"}, {"Sigma", "Σ"},
      {"Phi", "Φ"}, {"Omega", "Ω"}, {"int", "∫"}, {"sum", "∑"}, {"prod", "∏"}, {"infty", "∞"},
      {"approx", "≈"}, {"le", "≤"}, {"leq", "≤"}, {"ge", "≥"}, {"geq", "≥"}, {"neq", "≠"}, {"ne", "≠"},
      {"partial", "∂"}, {"nabla", "∇"}, {"cdot", "·"}, {"times", "×"}, {"pm", "±"}, {"propto", "∝"},
      {"sim", "∼"}, {"in", "∈"}, {"to", "→"}, {"rightarrow", "→"}, {"leftarrow", "←"}, {"Rightarrow", "⇒"},
      {"iff", "⇔"}, {"mapsto", "↦"}, {"langle", "⟨"}, {"rangle", "⟩"}, {"lVert", "‖"}, {"rVert", "‖"},
      {"Vert", "‖"}, {"|", "‖"}, {"vert", "|"}, {"lvert", "|"}, {"rvert", "|"}, {"ldots", "…"}, {"dots", "…"},
      {"cdots", "⋯"}, {"forall", "∀"}, {"cup", "∪"}, {"cap", "∩"}, {"lfloor", "⌊"}, {"rfloor", "⌋"}, {"lceil", "⌈"}, {"rceil", "⌉"},
      {"quad", "\u2003"}, {"qquad", "\u2003\u2003"}, {",", " "}, {";", " "}, {":", " "}, {"!", ""}, {" ", " "}, {"left", ""},
      {"right", ""}, {"big", ""}, {"Big", ""}, {"bigg", ""}, {"Bigg", ""}, {"displaystyle", ""}, {"{", "{"},
      {"}", "}"}, {"_", "_"}, {"%", "%"}, {"\\", "; "}, {"equiv", "≡"}, {"circ", "∘"}, {"star", "⋆"},
      {"ell", "ℓ"}, {"perp", "⊥"}, {"hbar", "ħ"}};
  return table;
}

// Upright function names: a thin space separates them from a following letter (cos θ, but cos²θ, max(...)).
bool isFunctionName(const std::string& name) {
  static const char* names[] = {"max", "min", "cos", "sin", "tan", "log", "ln", "exp", "arg", "lim", "det", "sup", "inf"};
  return std::any_of(std::begin(names), std::end(names), [&](const char* n) { return name == n; });
}

// Wrappers whose argument is shown as is.
bool isTextWrapper(const std::string& name) {
  return name == "mathbf" || name == "mathrm" || name == "text" || name == "mathit" || name == "mathcal" ||
         name == "boldsymbol" || name == "textrm" || name == "mathsf" || name == "bm" || name == "mathrel" ||
         name == "mathbin" || name == "mathop" || name == "textbf" || name == "textit" || name == "mathbb";
}

// The UTF-8 code points of `s`, each as a string.
std::vector<std::string> splitCodePoints(const std::string& s) {
  std::vector<std::string> out;
  for (const char c : s) {
    if ((static_cast<unsigned char>(c) & 0xC0) == 0x80 && !out.empty())
      out.back() += c;
    else
      out.emplace_back(1, c);
  }
  return out;
}

using Runs = std::vector<MathRun>;

void append(Runs& out, const std::string& text, int script = 0) {
  if (text.empty()) return;
  if (!out.empty() && out.back().script == script)
    out.back().text += text;
  else
    out.push_back({text, script});
}

void append(Runs& out, const Runs& more) {
  for (const MathRun& r : more) append(out, r.text, r.script);
}

std::string joined(const Runs& runs) {
  std::string out;
  for (const MathRun& r : runs) {
    if (r.script == 0) {
      out += r.text;
      continue;
    }
    const bool spaced = r.text.find(' ') != std::string::npos;
    out += (r.script < 0 ? "_" : "^") + (spaced ? "(" + r.text + ")" : r.text);
  }
  return out;
}

// Unicode sub- and superscript forms (the ones DejaVu Sans draws); others are drawn as small runs.
const std::map<std::string, std::string>& subscripts() {
  static const std::map<std::string, std::string> sub = {
      {"0", "₀"}, {"1", "₁"}, {"2", "₂"}, {"3", "₃"}, {"4", "₄"}, {"5", "₅"}, {"6", "₆"}, {"7", "₇"}, {"8", "₈"},
      {"9", "₉"}, {"+", "₊"}, {"−", "₋"}, {"=", "₌"}, {"(", "₍"}, {")", "₎"}, {"a", "ₐ"}, {"e", "ₑ"}, {"o", "ₒ"},
      {"x", "ₓ"}, {"h", "ₕ"}, {"k", "ₖ"}, {"l", "ₗ"}, {"m", "ₘ"}, {"n", "ₙ"}, {"p", "ₚ"}, {"s", "ₛ"}, {"t", "ₜ"},
      {"i", "ᵢ"}, {"j", "ⱼ"}, {"r", "ᵣ"}, {"u", "ᵤ"}, {"v", "ᵥ"}};
  return sub;
}
const std::map<std::string, std::string>& superscripts() {
  static const std::map<std::string, std::string> sup = {
      {"0", "⁰"}, {"1", "¹"}, {"2", "²"}, {"3", "³"}, {"4", "⁴"}, {"5", "⁵"}, {"6", "⁶"}, {"7", "⁷"}, {"8", "⁸"},
      {"9", "⁹"}, {"+", "⁺"}, {"−", "⁻"}, {"=", "⁼"}, {"(", "⁽"}, {")", "⁾"}, {"n", "ⁿ"}, {"i", "ⁱ"}};
  return sup;
}

// A script argument in Unicode sub/superscript characters when every character has one, else a small run.
Runs script(const Runs& arg, int level) {
  const auto& table = level < 0 ? subscripts() : superscripts();
  bool plain = std::all_of(arg.begin(), arg.end(), [](const MathRun& r) { return r.script == 0; });
  std::string mapped;
  if (plain)
    for (const std::string& cp : splitCodePoints(joined(arg))) {
      const auto it = table.find(cp);
      if (it == table.end()) {
        plain = false;
        break;
      }
      mapped += it->second;
    }
  Runs out;
  if (plain && !mapped.empty()) {
    append(out, mapped);
    return out;
  }
  for (const MathRun& r : arg) append(out, r.text, level);
  return out;
}

// Whether a fraction's or root's part needs parentheses to read right on one line.
bool needsGroup(const Runs& runs) {
  const std::string text = joined(runs);
  auto cps = splitCodePoints(text);
  if (cps.size() <= 1) return false;
  if (cps.front() == "√") cps.erase(cps.begin());  // √(...) is grouped already
  static const std::vector<std::pair<std::string, std::string>> delimiters = {
      {"(", ")"}, {"‖", "‖"}, {"|", "|"}, {"⟨", "⟩"}, {"[", "]"}, {"⌊", "⌋"}};
  for (const auto& [open, close] : delimiters)
    if (cps.front() == open && cps.back() == close &&
        std::count(cps.begin() + 1, cps.end() - 1, open) == 0 && std::count(cps.begin() + 1, cps.end() - 1, close) == 0)
      return false;
  if (std::isdigit(static_cast<unsigned char>(text[0])) && cps.size() > 1 && !std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.'; }))
    return true;  // 2π: a product
  for (const char* op : {" ", "+", "−", "-", "·", "×", "/", "=", ",", "<", ">", "≤", "≥"})
    if (text.find(op) != std::string::npos) return true;
  return false;
}

Runs grouped(const Runs& runs) {
  if (!needsGroup(runs)) return runs;
  Runs out;
  append(out, "(");
  append(out, runs);
  append(out, ")");
  return out;
}

struct MathReader {
  const std::string& s;
  size_t i = 0;

  void skipSpaces() {
    while (i < s.size() && s[i] == ' ') ++i;
  }

  // The text of a {...} group (i at the brace), braces removed.
  std::string group() {
    int depth = 0;
    const size_t start = ++i;
    for (; i < s.size(); ++i) {
      if (s[i] == '\\' && i + 1 < s.size()) {
        ++i;
        continue;
      }
      if (s[i] == '{') ++depth;
      if (s[i] == '}' && depth-- == 0) break;
    }
    const std::string inner = s.substr(start, i - start);
    if (i < s.size()) ++i;
    return inner;
  }

  // One argument: {...} or a single character / command.
  Runs argument() {
    skipSpaces();
    if (i >= s.size()) return {};
    if (s[i] == '{') return mathRuns(group());
    if (s[i] == '\\') return command();
    Runs out;
    append(out, character());
    return out;
  }

  std::string character() {  // one code point at i
    const char ch = s[i++];
    if (ch == '-') return "−";
    if (ch == '~') return " ";
    if (ch == '&') return "\u2003";  // an alignment point: a quad
    std::string cp(1, ch);
    while (i < s.size() && (static_cast<unsigned char>(s[i]) & 0xC0) == 0x80) cp += s[i++];
    return cp;
  }

  // Whether spaces and then a closing bracket come next.
  bool closingNext() const {
    size_t j = i;
    while (j < s.size() && s[j] == ' ') ++j;
    for (const char* close : {")", "]", "\\right", "\\rvert", "\\rVert", "\\rangle", "\\rfloor", "\\rceil"})
      if (s.compare(j, std::strlen(close), close) == 0) return true;
    return false;
  }

  Runs command() {  // at the backslash
    ++i;
    const size_t start = i;
    while (i < s.size() && std::isalpha(static_cast<unsigned char>(s[i]))) ++i;
    if (i == start && i < s.size()) ++i;  // \, \| \{ ...
    const std::string name = s.substr(start, i - start);
    Runs out;
    if (name == "lvert" || name == "lVert" || name == "langle" || name == "lfloor" || name == "lceil" || name == "left") {
      append(out, symbols().count(name) ? symbols().at(name) : "");
      skipSpaces();  // no space inside a bracket
      return out;
    }
    if (name == "frac" || name == "dfrac" || name == "tfrac") {
      const Runs a = argument(), b = argument();
      append(out, grouped(a));
      append(out, "/");
      append(out, grouped(b));
    } else if (name == "sqrt") {
      skipSpaces();
      if (i < s.size() && s[i] == '[') i = std::min(s.size(), s.find(']', i) + 1);  // \sqrt[n]: shown as √
      const Runs a = argument();
      append(out, "√");
      if (codePoints(joined(a)) > 1) {  // the root's argument grouped: √(1 − x), never √1 − x
        append(out, "(");
        append(out, a);
        append(out, ")");
      } else {
        append(out, a);
      }
    } else if (isTextWrapper(name)) {
      out = argument();
    } else if (name == "operatorname") {
      out = argument();
      functionSpace(out);
    } else if (name == "hat" || name == "vec" || name == "bar" || name == "tilde" || name == "dot") {
      const char* mark = name == "hat" ? "\xCC\x82" : name == "vec" ? "\xE2\x83\x97" : name == "bar" ? "\xCC\x84"
                         : name == "dot" ? "\xCC\x87" : "\xCC\x83";
      out = argument();
      if (!out.empty()) out.back().text += mark;
    } else if (name == "begin" || name == "end") {
      skipSpaces();
      const std::string env = i < s.size() && s[i] == '{' ? group() : "";
      if (env == "cases") append(out, name == "begin" ? "{ " : " }");  // closed too: its rows stay together
    } else if (isFunctionName(name)) {
      append(out, name);
      functionSpace(out);
    } else {
      const auto it = symbols().find(name);
      append(out, it != symbols().end() ? it->second : name);
    }
    return out;
  }

  // After an upright function name: a thin space if a letter or a command (not a script, not a bracket) follows.
  void functionSpace(Runs& out) {
    size_t j = i;
    while (j < s.size() && s[j] == ' ') ++j;
    if (j < s.size() && (std::isalpha(static_cast<unsigned char>(s[j])) || (s[j] == '\\' && j + 1 < s.size() && std::isalpha(static_cast<unsigned char>(s[j + 1])))))
      append(out, "\xE2\x80\x89");  // U+2009 thin space
  }
};

}  // namespace

size_t codePoints(const std::string& s) {
  return static_cast<size_t>(std::count_if(s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

// Math spacing as TeX sets it: the source's spaces are not spacing, so a space next to a space (\, or
// a space typed after \cos) is dropped, as is one after an opening bracket, and a quad (an em space),
// a comma or a semicolon takes none before it.
void tidySpaces(Runs& runs) {
  constexpr std::string_view kEm = "\u2003", kThin = "\u2009";
  std::string* last = nullptr;  // the text written so far, across runs
  for (MathRun& r : runs) {
    std::string out;
    for (const std::string& cp : splitCodePoints(r.text)) {
      std::string& before = out.empty() && last ? *last : out;
      const bool afterSpace = before.ends_with(' ') || before.ends_with(kEm) || before.ends_with(kThin);
      if (cp == " " && (afterSpace || before.ends_with('(') || before.ends_with('['))) continue;
      if (cp == kEm || cp == "," || cp == ";")  // punctuation takes no space before it
        while (before.ends_with(' ')) before.pop_back();
      out += cp;
    }
    r.text = std::move(out);
    if (!r.text.empty()) last = &r.text;
  }
  std::erase_if(runs, [](const MathRun& r) { return r.text.empty(); });
}

std::vector<MathRun> mathRuns(const std::string& latex) {
  MathReader r{latex};
  Runs out;
  while (r.i < latex.size()) {
    const char ch = latex[r.i];
    if (ch == '\\') {
      append(out, r.command());
    } else if (ch == ' ' && r.closingNext()) {  // no space inside a bracket: (a + b), |x|
      ++r.i;
    } else if (ch == '^' || ch == '_') {
      ++r.i;
      append(out, script(r.argument(), ch == '^' ? 1 : -1));
    } else if (ch == '{') {
      append(out, mathRuns(r.group()));
    } else if (ch == '}') {
      ++r.i;
    } else if (ch == '\n' || ch == '\t') {
      append(out, " ");
      ++r.i;
    } else {
      append(out, r.character());
    }
  }
  tidySpaces(out);
  return out;
}

std::string mathAsText(const std::string& latex) { return joined(mathRuns(latex)); }

namespace {

// Where a line may break, most willingly first: a formula breaks at a kind only where its part
// between breaks of the kinds before does not fit a line of its own (display math as TeX sets it).
enum Glue : int {
  kFreeBreak = 0,    // between words, or a wide gap (\quad) between clauses of a formula
  kBeforeRelation,   // before =, ≈, ≤, ... or after a comma, outside brackets
  kBeforeOperator,   // before +, −, ·, × outside brackets
  kBetweenFactors,   // a space between factors outside brackets: A/B C/D
};

bool isOneOf(const std::string& cp, std::initializer_list<std::string_view> set) {
  return std::find(set.begin(), set.end(), cp) != set.end();
}
bool isRelation(const std::string& cp) {
  return isOneOf(cp, {"=", "≈", "≤", "≥", "<", ">", "≠", "∝", "⇔", "⇒", "→", "≡", "∼", "∈", "↦"});
}
bool isOperator(const std::string& cp) { return isOneOf(cp, {"+", "−", "·", "×", "±"}); }
// Nothing breaks after these: an operator binds to what follows, as does a big operator or an opening bracket.
bool bindsForward(const std::string& cp) {
  return isRelation(cp) || isOperator(cp) || isOneOf(cp, {"/", "∑", "∏", "∫", "√", "(", "[", "{", "⟨"});
}
// The Unicode sub- and superscript characters mathRuns writes: a formula's last base character is before them.
bool isScriptCharacter(const std::string& cp) {
  static const std::set<std::string> scripts = [] {
    std::set<std::string> all;
    for (const auto* table : {&subscripts(), &superscripts()})
      for (const auto& [plain, script] : *table) all.insert(script);
    return all;
  }();
  return scripts.count(cp) > 0;
}

}  // namespace

std::vector<LaidLine> wrapSpans(const std::vector<TextSpan>& spans, float width, const MeasureText& measure,
                                float minScale) {
  constexpr float kSlightShrink = 0.9f;  // a part this much too wide is shrunk, not broken
  // Units that never break inside, each with the spaces after it, the kind of break before it and
  // whether a line break follows.
  struct Unit {
    std::vector<LaidPiece> pieces;
    std::vector<LaidPiece> trail;  // spaces: dropped at the end of a line
    int glue = kFreeBreak;
    bool breakAfter = false;
    float w = 0.0f, trailW = 0.0f;
  };
  std::vector<Unit> units(1);
  const auto put = [](std::vector<LaidPiece>& pieces, size_t span, const std::string& text) {
    if (text.empty()) return;
    if (!pieces.empty() && pieces.back().span == span)
      pieces.back().text += text;
    else
      pieces.push_back({span, text, 0.0f, 0.0f});
  };
  const auto startUnit = [&] {  // a new unit after spaces, at a free break
    if (!units.back().trail.empty()) units.emplace_back();
  };
  int depth = 0;                   // brackets open in the current formula
  bool inBars = false, inNorm = false;  // inside |...|, ‖...‖
  std::string lastBase;            // the formula's last character on the baseline, spaces and scripts aside
  for (size_t k = 0; k < spans.size(); ++k) {
    const std::string& t = spans[k].text;
    if (spans[k].style == SpanStyle::Math) {
      // A formula is glued to its neighbours. Outside brackets and scripts it may break at a wide gap
      // (\quad, two spaces or more) freely, and at a space before a relation, an operator or a factor
      // when it must; never after an operator.
      const std::vector<std::string> cps = splitCodePoints(t);
      std::string run;  // the text since the last break
      for (size_t i = 0; i < cps.size(); ++i) {
        const std::string& c = cps[i];
        const bool space = c == " " || c == "\u2003";
        if (!space || depth > 0 || inBars || inNorm || lastBase.empty() || spans[k].script != 0) {
          depth += isOneOf(c, {"(", "[", "{", "⟨"}) ? 1 : isOneOf(c, {")", "]", "}", "⟩"}) ? -1 : 0;
          inBars = inBars != (c == "|");
          inNorm = inNorm != (c == "‖");
          if (spans[k].script == 0 && !space && !isScriptCharacter(c)) lastBase = c;
          run += c;
          continue;
        }
        size_t end = i;  // past the spaces
        std::string gap;
        while (end < cps.size() && (cps[end] == " " || cps[end] == "\u2003")) gap += cps[end++];
        const bool wide = gap != " ";
        const std::string next = end < cps.size() ? cps[end] : "";
        int glue = kFreeBreak;
        if (!wide) {
          if (next.empty() || bindsForward(lastBase))
            glue = -1;  // no break
          else
            glue = lastBase == "," || isRelation(next) ? kBeforeRelation
                   : isOperator(next)                  ? kBeforeOperator
                                                       : kBetweenFactors;
        }
        if (glue < 0) {
          run += gap;
        } else {
          startUnit();
          put(units.back().pieces, k, run);
          put(units.back().trail, k, gap);
          units.emplace_back();
          units.back().glue = glue;
          run.clear();
        }
        i = end - 1;
      }
      if (!run.empty()) {
        startUnit();
        put(units.back().pieces, k, run);
      }
      continue;
    }
    depth = 0;
    inBars = inNorm = false;
    lastBase.clear();
    size_t i = 0;
    while (i < t.size()) {
      if (t[i] == '\n') {
        units.back().breakAfter = true;
        units.emplace_back();
        ++i;
      } else if (t[i] == ' ') {
        const size_t end = std::min(t.find_first_not_of(' ', i), t.size());
        put(units.back().trail, k, t.substr(i, end - i));
        i = end;
      } else {
        startUnit();
        const size_t end = std::min(t.find_first_of(" \n", i), t.size());
        put(units.back().pieces, k, t.substr(i, end - i));
        i = end;
      }
    }
  }
  for (Unit& u : units) {
    for (LaidPiece& p : u.pieces) u.w += (p.width = measure(p.text, spans[p.span]));
    for (LaidPiece& p : u.trail) u.trailW += (p.width = measure(p.text, spans[p.span]));
  }

  std::vector<LaidLine> lines(1);
  float x = 0.0f;  // pen position on the current line, trailing spaces included
  const auto newLine = [&] {
    lines.emplace_back();
    x = 0.0f;
  };
  const auto widthOf = [&](size_t a, size_t b) {  // units [a, b) on one line, without the last one's spaces
    float w = 0.0f;
    for (size_t i = a; i < b; ++i) w += units[i].w + (i + 1 < b ? units[i].trailW : 0.0f);
    return w;
  };
  // Units [a, b) at the pen, drawn at `scale`.
  const auto place = [&](size_t a, size_t b, float scale) {
    for (size_t i = a; i < b; ++i) {
      const Unit& u = units[i];
      LaidLine& line = lines.back();
      line.scale = scale;
      for (LaidPiece p : u.pieces) {
        p.x = x * scale;
        p.width *= scale;
        x += p.width / scale;
        line.pieces.push_back(p);
        line.width = x * scale;
      }
      if (!line.pieces.empty()) x += u.trailW;  // no spaces at the start of a line
      if (u.breakAfter) newLine();
    }
  };
  // Units [a, b): on this line if they fit, else on the next, shrunk a little if need be; too wide
  // for that, broken at the most willing of their inner breaks, each part laid out the same way; too
  // wide and unbreakable, alone on a line, shrunk (and maybe still too wide).
  const std::function<void(size_t, size_t)> lay = [&](size_t a, size_t b) {
    const float w = widthOf(a, b);
    if (x > 0.0f && x + w <= width) {
      place(a, b, 1.0f);
      return;
    }
    if (w <= width || width <= 0.0f) {
      if (x > 0.0f) newLine();
      place(a, b, 1.0f);
      return;
    }
    if (w * kSlightShrink <= width) {  // a line of its own, a little smaller, reads better than a break
      if (!lines.back().pieces.empty()) newLine();
      place(a, b, width / w);
      if (!lines.back().pieces.empty()) newLine();
      return;
    }
    int preferred = INT_MAX;  // the most willing break inside
    for (size_t i = a + 1; i < b; ++i) preferred = std::min(preferred, units[i].glue);
    if (preferred == INT_MAX) {
      if (!lines.back().pieces.empty()) newLine();
      place(a, b, std::max(minScale, width / w));
      if (!lines.back().pieces.empty()) newLine();
      return;
    }
    for (size_t from = a, i = a + 1; i <= b; ++i)
      if (i == b || units[i].glue == preferred) {
        lay(from, i);
        from = i;
      }
  };
  for (size_t from = 0, i = 1; i <= units.size(); ++i)
    if (i == units.size() || units[i].glue == kFreeBreak) {
      lay(from, i);
      from = i;
    }
  if (lines.size() > 1 && lines.back().pieces.empty()) lines.pop_back();
  return lines;
}

std::vector<TextBlock> slideText(const std::string& markdown) {
  Collector c;
  MD_PARSER parser{};
  parser.flags = MD_DIALECT_GITHUB | MD_FLAG_LATEXMATHSPANS;
  parser.enter_block = enterBlock;
  parser.leave_block = leaveBlock;
  parser.enter_span = enterSpan;
  parser.leave_span = leaveSpan;
  parser.text = text;
  md_parse(markdown.data(), static_cast<MD_SIZE>(markdown.size()), &parser, &c);
  std::erase_if(c.blocks, [](const TextBlock& b) { return b.spans.empty() && b.kind != BlockKind::Figure; });
  return c.blocks;
}

}  // namespace ll
