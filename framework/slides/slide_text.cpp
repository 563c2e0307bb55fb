#include "slides/slide_text.h"

#include <algorithm>
#include <cctype>
#include <map>

#include <md4c.h>

#include "slides/deck.h"

namespace ll {

namespace {

struct Collector {
  std::vector<TextBlock> blocks;
  std::vector<int> lists;       // per open list: next number, or -1 for bullets
  std::vector<SpanStyle> styles;  // open spans
  int paragraphLevel = 0;  // list depth of the paragraph a display equation interrupted

  TextBlock& open(BlockKind kind, int level = 0, std::string marker = "") {
    blocks.push_back({kind, level, std::move(marker), {}});
    return blocks.back();
  }
  SpanStyle style() const { return styles.empty() ? SpanStyle::Plain : styles.back(); }
  void add(const std::string& text, SpanStyle s) {
    if (blocks.empty()) open(BlockKind::Paragraph);
    auto& spans = blocks.back().spans;
    if (!spans.empty() && spans.back().style == s)
      spans.back().text += text;
    else
      spans.push_back({text, s});
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
  if (type == MD_SPAN_LATEXMATH_DISPLAY) c.open(BlockKind::Paragraph, c.paragraphLevel);
  return 0;
}

int text(MD_TEXTTYPE type, const MD_CHAR* data, MD_SIZE size, void* user) {
  auto& c = *static_cast<Collector*>(user);
  const std::string s(data, size);
  switch (type) {
    case MD_TEXT_SOFTBR:
      c.add(" ", c.style());
      break;
    case MD_TEXT_BR:
      c.add("\n", c.style());
      break;
    case MD_TEXT_LATEXMATH:
      c.add(mathAsText(s), SpanStyle::Math);
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
      {"mapsto", "↦"}, {"langle", "⟨"}, {"rangle", "⟩"}, {"lVert", "‖"}, {"rVert", "‖"}, {"|", "‖"},
      {"ldots", "…"}, {"dots", "…"}, {"cdots", "⋯"}, {"forall", "∀"}, {"cup", "∪"}, {"cap", "∩"},
      {"sqrt", "√"}, {"lfloor", "⌊"}, {"rfloor", "⌋"}, {"quad", "  "}, {"qquad", "    "}, {",", " "},
      {";", " "}, {"!", ""}, {" ", " "}, {"left", ""}, {"right", ""}, {"big", ""}, {"Big", ""},
      {"displaystyle", ""}, {"max", "max"}, {"min", "min"}, {"cos", "cos"}, {"sin", "sin"}, {"log", "log"},
      {"ln", "ln"}, {"exp", "exp"}, {"arg", "arg"}, {"lim", "lim"}, {"{", "{"}, {"}", "}"}, {"_", "_"},
      {"equiv", "≡"}, {"circ", "∘"}, {"star", "⋆"}, {"ell", "ℓ"}, {"perp", "⊥"}, {"hbar", "ħ"}};
  return table;
}

// Wrappers whose argument is shown as is.
bool isTextWrapper(const std::string& name) {
  return name == "mathbf" || name == "mathrm" || name == "text" || name == "mathit" || name == "mathcal" ||
         name == "boldsymbol" || name == "operatorname" || name == "textrm" || name == "mathsf" || name == "bm";
}

// Characters in UTF-8 text (bytes that do not continue a sequence).
size_t codePoints(const std::string& s) {
  return static_cast<size_t>(std::count_if(s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

std::string superscript(const std::string& s) {
  static const std::map<char, std::string> sup = {{'0', "⁰"}, {'1', "¹"}, {'2', "²"}, {'3', "³"}, {'4', "⁴"},
                                                  {'5', "⁵"}, {'6', "⁶"}, {'7', "⁷"}, {'8', "⁸"}, {'9', "⁹"},
                                                  {'+', "⁺"}, {'-', "⁻"}, {'n', "ⁿ"}, {'i', "ⁱ"}};
  std::string out;
  for (const char ch : s) {
    const auto it = sup.find(ch);
    if (it == sup.end()) return codePoints(s) > 1 ? "^(" + s + ")" : "^" + s;
    out += it->second;
  }
  return out;
}

// Unicode subscripts exist for digits and a few letters only; others keep the underscore.
std::string subscript(const std::string& s) {
  static const std::map<char, std::string> sub = {
      {'0', "₀"}, {'1', "₁"}, {'2', "₂"}, {'3', "₃"}, {'4', "₄"}, {'5', "₅"}, {'6', "₆"}, {'7', "₇"},
      {'8', "₈"}, {'9', "₉"}, {'+', "₊"}, {'-', "₋"}, {'a', "ₐ"}, {'e', "ₑ"}, {'o', "ₒ"}, {'x', "ₓ"},
      {'h', "ₕ"}, {'k', "ₖ"}, {'l', "ₗ"}, {'m', "ₘ"}, {'n', "ₙ"}, {'p', "ₚ"}, {'s', "ₛ"}, {'t', "ₜ"},
      {'i', "ᵢ"}, {'j', "ⱼ"}, {'r', "ᵣ"}, {'u', "ᵤ"}, {'v', "ᵥ"}};
  std::string out;
  for (const char ch : s) {
    const auto it = sub.find(ch);
    if (it == sub.end()) return "_" + (codePoints(s) > 1 ? "(" + s + ")" : s);
    out += it->second;
  }
  return out;
}

struct MathReader {
  const std::string& s;
  size_t i = 0;

  // One argument: {...} or a single character / command.
  std::string argument() {
    while (i < s.size() && s[i] == ' ') ++i;
    if (i >= s.size()) return "";
    if (s[i] == '{') {
      int depth = 0;
      const size_t start = ++i;
      for (; i < s.size(); ++i) {
        if (s[i] == '{') ++depth;
        if (s[i] == '}' && depth-- == 0) break;
      }
      const std::string inner = s.substr(start, i - start);
      if (i < s.size()) ++i;
      return mathAsText(inner);
    }
    if (s[i] == '\\') return command();
    return std::string(1, s[i++]);
  }

  std::string command() {  // at the backslash
    ++i;
    size_t start = i;
    while (i < s.size() && std::isalpha(static_cast<unsigned char>(s[i]))) ++i;
    if (i == start && i < s.size()) ++i;  // \, \| \{ ...
    const std::string name = s.substr(start, i - start);
    if (name == "frac" || name == "dfrac" || name == "tfrac") {
      const std::string a = argument(), b = argument();
      const auto wrap = [](const std::string& x) { return x.size() > 1 ? "(" + x + ")" : x; };
      return wrap(a) + "/" + wrap(b);
    }
    if (isTextWrapper(name)) return argument();
    if (name == "hat" || name == "vec" || name == "bar" || name == "tilde") {
      const char* mark = name == "hat" ? "\xCC\x82" : name == "vec" ? "\xE2\x83\x97" : name == "bar" ? "\xCC\x84" : "\xCC\x83";
      return argument() + mark;
    }
    const auto it = symbols().find(name);
    return it != symbols().end() ? it->second : name;
  }
};

}  // namespace

std::string mathAsText(const std::string& latex) {
  MathReader r{latex};
  std::string out;
  while (r.i < latex.size()) {
    const char ch = latex[r.i];
    if (ch == '\\') {
      out += r.command();
    } else if (ch == '^') {
      ++r.i;
      out += superscript(r.argument());
    } else if (ch == '_') {
      ++r.i;
      out += subscript(r.argument());
    } else if (ch == '{' || ch == '}') {
      ++r.i;
    } else if (ch == '\n') {
      out += ' ';
      ++r.i;
    } else {
      out += ch;
      ++r.i;
    }
  }
  return out;
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
