#include "gui/slide_panel.h"

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <string>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "gui/presenter.h"

namespace ll::gui {

namespace {

constexpr const char* kBoldFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";
constexpr const char* kMonoFont = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
constexpr float kHeadingScale = 1.45f, kTitleScale = 1.9f;

// Basic Latin + Latin-1 and Latin Extended-A (names: Šidák), combining accents, Greek, punctuation, super- and
// subscripts (and i, j, r, u, v), combining arrow, letterlike symbols, arrows, math operators,
// floor brackets, angle brackets. Zero-terminated pairs.
constexpr ImWchar kRanges[] = {0x0020, 0x00FF, 0x0100, 0x017F, 0x0300, 0x036F, 0x0370, 0x03FF, 0x1D62, 0x1D65, 0x2000, 0x206F,
                               0x2070, 0x209F, 0x20D7, 0x20D7, 0x2100, 0x214F, 0x2190, 0x21FF, 0x2200, 0x22FF,
                               0x2308, 0x230B, 0x27E8, 0x27E9, 0x2C7C, 0x2C7C, 0};

const ImVec4 kText(0.93f, 0.93f, 0.95f, 1.0f), kHeading(0.55f, 0.78f, 1.0f, 1.0f), kCode(1.0f, 0.80f, 0.45f, 1.0f),
    kMath(0.70f, 0.95f, 0.75f, 1.0f), kDim(0.6f, 0.6f, 0.65f, 1.0f), kEmphasis(0.95f, 0.85f, 1.0f, 1.0f);

void recordWidget(AppState& app, const std::string& name) {
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  app.widgetRects[name] = {a.x, a.y, b.x - a.x, b.y - a.y};
}

ImFont* fontFor(const PresenterState& p, SpanStyle style, ImFont* base) {
  if (style == SpanStyle::Code && p.code) return p.code;
  if (style == SpanStyle::Strong && p.bold && base == ImGui::GetIO().Fonts->Fonts[0]) return p.bold;
  return base;
}

ImVec4 colourFor(SpanStyle style, const ImVec4& base) {
  switch (style) {
    case SpanStyle::Code:
      return kCode;
    case SpanStyle::Math:
      return kMath;
    case SpanStyle::Emphasis:
      return kEmphasis;
    case SpanStyle::Strong:
    case SpanStyle::Plain:
      break;
  }
  return base;
}

constexpr float kScriptScale = 0.7f;  // sub- and superscripts without a Unicode form, drawn small

// Word-wrapped text of mixed spans, starting at the cursor, lines from `left` to `right` (window
// coordinates). A formula breaks only where it does not fit (wrapSpans); a part that cannot break
// is shrunk, and if still too wide the line runs past `right` and the panel scrolls sideways.
// `centre` centres each line (display math).
void drawSpans(const PresenterState& p, const std::vector<TextSpan>& spans, ImFont* base, const ImVec4& colour,
               float left, float right, bool centre = false) {
  const float globalScale = ImGui::GetFontSize() / ImGui::GetFont()->FontSize;  // window and UI font scale
  const auto sizeOf = [&](const TextSpan& s) {
    return fontFor(p, s.style, base)->FontSize * globalScale * (s.script != 0 ? kScriptScale : 1.0f);
  };
  const MeasureText measure = [&](const std::string& text, const TextSpan& s) {
    return fontFor(p, s.style, base)->CalcTextSizeA(sizeOf(s), FLT_MAX, 0.0f, text.c_str(), text.c_str() + text.size()).x;
  };
  const float width = std::max(right - left, 1.0f);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  for (const LaidLine& line : wrapSpans(spans, width, measure)) {
    const float baseSize = base->FontSize * globalScale * line.scale;
    bool sub = false, sup = false;
    for (const LaidPiece& piece : line.pieces) {
      sub = sub || spans[piece.span].script < 0;
      sup = sup || spans[piece.span].script > 0;
    }
    const float top = sup ? baseSize * 0.12f : 0.0f;  // room above for superscripts, below for subscripts
    const float height = top + baseSize + (sub ? baseSize * 0.2f : 0.0f);
    ImGui::SetCursorPosX(centre && line.width < width ? left + (width - line.width) * 0.5f : left);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    for (const LaidPiece& piece : line.pieces) {
      const TextSpan& span = spans[piece.span];
      const float size = sizeOf(span) * line.scale;
      const float dy = span.script < 0 ? baseSize * 0.42f : span.script > 0 ? -baseSize * 0.1f : 0.0f;
      draw->AddText(fontFor(p, span.style, base), size, ImVec2(origin.x + piece.x, origin.y + top + dy),
                    ImGui::GetColorU32(colourFor(span.style, colour)), piece.text.c_str(),
                    piece.text.c_str() + piece.text.size());
    }
    ImGui::Dummy(ImVec2(std::max(line.width, 1.0f), height));  // reserves the line (and widens the scroll area)
  }
}

// A code block in a child window of its own: shrunk a little to fit, else scrolled sideways, never clipped.
void drawCode(const PresenterState& p, const std::string& code, int id, float left, float width) {
  ImFont* font = p.code ? p.code : ImGui::GetIO().Fonts->Fonts[0];
  std::string text = code;
  while (!text.empty() && text.back() == '\n') text.pop_back();
  ImGui::PushFont(font);
  const ImGuiStyle& style = ImGui::GetStyle();
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  const float inner = width - style.WindowPadding.x * 2.0f;
  // (1 % to spare: the glyphs' advances, scaled and rounded, can add up to a pixel or two more than
  // size.x * scale, which would show a scrollbar for nothing.)
  const float scale = size.x > inner ? std::max(0.75f, 0.99f * inner / size.x) : 1.0f;
  const bool scrolls = size.x * scale > inner;
  const float height = size.y * scale + style.WindowPadding.y * 2.0f + (scrolls ? style.ScrollbarSize : 0.0f);
  ImGui::SetCursorPosX(left);
  ImGui::PushStyleColor(ImGuiCol_ChildBg, ImVec4(0.0f, 0.0f, 0.0f, 0.25f));
  ImGui::PushID(id);
  ImGui::BeginChild("##code", ImVec2(width, height), false,
                    ImGuiWindowFlags_HorizontalScrollbar | ImGuiWindowFlags_NoScrollWithMouse |
                        ImGuiWindowFlags_AlwaysUseWindowPadding);
  ImGui::SetWindowFontScale(scale);
  ImGui::PushStyleColor(ImGuiCol_Text, kCode);
  ImGui::TextUnformatted(text.c_str(), text.c_str() + text.size());
  ImGui::PopStyleColor();
  ImGui::EndChild();
  ImGui::PopID();
  ImGui::PopStyleColor();
  ImGui::PopFont();
}

void drawBlocks(AppState& app, const std::vector<TextBlock>& blocks, float width) {
  const PresenterState& p = app.presenter;
  ImFont* body = ImGui::GetIO().Fonts->Fonts[0];
  const float indentStep = ImGui::GetFontSize() * 1.4f;
  const float base = ImGui::GetCursorPosX();
  int codeBlock = 0;
  for (const TextBlock& b : blocks) {
    switch (b.kind) {
      case BlockKind::Heading: {
        ImFont* f = b.level == 1 && p.title ? p.title : p.heading ? p.heading : body;
        drawSpans(p, b.spans, f, kHeading, base, base + width);
        ImGui::Spacing();
        break;
      }
      case BlockKind::ListItem: {
        const float left = base + indentStep * static_cast<float>(b.level);
        ImGui::SetCursorPosX(left - indentStep * 0.8f);
        ImGui::TextColored(kHeading, "%s", b.marker.c_str());
        ImGui::SameLine(0.0f, 0.0f);
        ImGui::SetCursorPosX(left);
        drawSpans(p, b.spans, body, kText, left, base + width);
        break;
      }
      case BlockKind::Code:  // the panel's whole width: code lines are long, and indenting them costs columns
        for (const TextSpan& s : b.spans) drawCode(p, s.text, ++codeBlock, base, std::max(width, 50.0f));
        break;
      case BlockKind::DisplayMath:
        ImGui::Spacing();
        drawSpans(p, b.spans, body, kMath, base, base + width, true);
        ImGui::Spacing();
        break;
      case BlockKind::TableRow:
        drawSpans(p, b.spans, b.level == 1 && p.bold ? p.bold : body, kText, base, base + width);
        break;
      case BlockKind::Figure: {
        const Slide& s = p.deck->slides[static_cast<size_t>(p.index)];
        const std::string what = s.preset && !s.preset->preset.description.empty() ? s.preset->preset.description
                                                                                  : "the panes on the right";
        ImGui::Spacing();
        ImGui::PushTextWrapPos(base + width);
        ImGui::TextColored(kDim, "Live: %s", what.c_str());
        ImGui::PopTextWrapPos();
        break;
      }
      case BlockKind::Paragraph:
        drawSpans(p, b.spans, body, kText, base + indentStep * static_cast<float>(b.level), base + width);
        break;
    }
    ImGui::Spacing();
  }
}

}  // namespace

const unsigned short* slideGlyphRanges() { return kRanges; }

void addSlideFonts(AppState& app, float pixels) {
  PresenterState& p = app.presenter;
  ImGuiIO& io = ImGui::GetIO();
  p.heading = io.Fonts->AddFontFromFileTTF(kBoldFont, std::round(pixels * kHeadingScale), nullptr, kRanges);
  p.title = io.Fonts->AddFontFromFileTTF(kBoldFont, std::round(pixels * kTitleScale), nullptr, kRanges);
  p.bold = io.Fonts->AddFontFromFileTTF(kBoldFont, std::round(pixels), nullptr, kRanges);
  p.code = io.Fonts->AddFontFromFileTTF(kMonoFont, std::round(pixels), nullptr, kRanges);
}

bool handleSlideKey(AppState& app, int key) {
  PresenterState& p = app.presenter;
  if (!p.active()) return false;
  switch (key) {
    case GLFW_KEY_RIGHT:
    case GLFW_KEY_DOWN:
    case GLFW_KEY_PAGE_DOWN:
    case GLFW_KEY_SPACE:
      requestStep(app, 1);
      return true;
    case GLFW_KEY_LEFT:
    case GLFW_KEY_UP:
    case GLFW_KEY_PAGE_UP:
    case GLFW_KEY_BACKSPACE:
      requestStep(app, -1);
      return true;
    case GLFW_KEY_HOME:
      requestStep(app, -p.count());
      return true;
    case GLFW_KEY_END:
      requestStep(app, p.count());
      return true;
    case GLFW_KEY_TAB:
      p.showControls = !p.showControls;
      return true;
    case GLFW_KEY_N:
      p.showNotes = !p.showNotes;
      return true;
    default:
      return false;
  }
}

void drawSlidePanel(AppState& app, float x, float y, float w, float h) {
  PresenterState& p = app.presenter;
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin("##slide", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  const ImGuiStyle& style = ImGui::GetStyle();
  const float buttonH = ImGui::GetFrameHeight() * 1.6f;
  const Slide& slide = p.deck->slides[static_cast<size_t>(p.index)];
  const std::string keys = std::string("Tab controls   N notes") + (slide.notes.empty() ? " (none)" : "") +
                           "   P labels   I stats   H hide   F11 full screen";
  const float keysH = ImGui::CalcTextSize(keys.c_str(), nullptr, false, w - 2.0f * style.WindowPadding.x).y;
  const float footer = buttonH + ImGui::GetTextLineHeightWithSpacing() + keysH + style.ItemSpacing.y * 4.0f;
  // A formula too wide even when shrunk widens the text: the panel then scrolls sideways.
  ImGui::BeginChild("##slidetext", ImVec2(0, std::max(h - footer - style.WindowPadding.y * 2.0f, 50.0f)), false,
                    ImGuiWindowFlags_HorizontalScrollbar);
  const float width = ImGui::GetContentRegionAvail().x - style.ScrollbarSize;
  drawBlocks(app, p.text[static_cast<size_t>(p.index)], width);
  if (p.showNotes && !p.notes[static_cast<size_t>(p.index)].empty()) {
    ImGui::Separator();
    ImGui::TextColored(kDim, "Notes");
    drawBlocks(app, p.notes[static_cast<size_t>(p.index)], width);
  }
  ImGui::EndChild();

  // Newest error of the last 8 s: a preset that did not apply must not go unseen.
  for (auto it = app.messages.rbegin(); it != app.messages.rend(); ++it)
    if (it->error && std::chrono::steady_clock::now() - it->when < std::chrono::seconds(8)) {
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", it->text.c_str());
      ImGui::PopTextWrapPos();
      break;
    }
  const float half = (ImGui::GetContentRegionAvail().x - style.ItemSpacing.x) * 0.5f;
  ImGui::BeginDisabled(p.index == 0);
  if (ImGui::Button("\xE2\x86\x90 Previous", ImVec2(half, buttonH))) requestStep(app, -1);
  ImGui::EndDisabled();
  recordWidget(app, "slides.previous");
  ImGui::SameLine();
  ImGui::BeginDisabled(p.index + 1 >= p.count());
  if (ImGui::Button("Next \xE2\x86\x92", ImVec2(half, buttonH))) requestStep(app, 1);
  ImGui::EndDisabled();
  recordWidget(app, "slides.next");
  ImGui::TextColored(kDim, "%d / %d   %s", p.index + 1, p.count(), p.deck->title.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, kDim);
  ImGui::TextWrapped("%s", keys.c_str());
  ImGui::PopStyleColor();
  ImGui::End();
}

}  // namespace ll::gui
