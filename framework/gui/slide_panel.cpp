#include "gui/slide_panel.h"

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

// Basic Latin + Latin-1, combining accents, Greek, punctuation, super- and
// subscripts (and i, j, r, u, v), combining arrow, letterlike symbols, arrows, math operators,
// floor brackets, angle brackets. Zero-terminated pairs.
constexpr ImWchar kRanges[] = {0x0020, 0x00FF, 0x0300, 0x036F, 0x0370, 0x03FF, 0x1D62, 0x1D65, 0x2000, 0x206F,
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

// Word-wrapped text of mixed spans, starting at the cursor, lines indented to `left`.
void drawSpans(const PresenterState& p, const std::vector<TextSpan>& spans, ImFont* base, const ImVec4& colour,
               float left, float right) {
  bool first = true;
  for (const TextSpan& span : spans) {
    ImGui::PushFont(fontFor(p, span.style, base));
    const ImVec4 c = colourFor(span.style, colour);
    size_t i = 0;
    while (i < span.text.size()) {
      if (span.text[i] == '\n') {
        ImGui::NewLine();
        ImGui::SetCursorPosX(left);
        first = true;
        ++i;
        continue;
      }
      // A word and the spaces after it; code and math keep their spaces inside one token.
      size_t end = span.text.find_first_of(" \n", i);
      if (end == std::string::npos) end = span.text.size();
      while (end < span.text.size() && span.text[end] == ' ') ++end;
      const std::string token = span.text.substr(i, end - i);
      i = end;
      const float width = ImGui::CalcTextSize(token.c_str()).x;
      if (!first) {
        ImGui::SameLine(0.0f, 0.0f);
        if (ImGui::GetCursorPosX() + width > right && ImGui::GetCursorPosX() > left + 1.0f) {
          ImGui::NewLine();
          ImGui::SetCursorPosX(left);
        }
      } else {
        ImGui::SetCursorPosX(left);
      }
      ImGui::TextColored(c, "%s", token.c_str());
      first = false;
    }
    ImGui::PopFont();
  }
}

void drawBlocks(AppState& app, const std::vector<TextBlock>& blocks, float width) {
  const PresenterState& p = app.presenter;
  ImFont* body = ImGui::GetIO().Fonts->Fonts[0];
  const float indentStep = ImGui::GetFontSize() * 1.4f;
  const float base = ImGui::GetCursorPosX();
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
        std::vector<TextSpan> spans = b.spans;
        drawSpans(p, spans, body, kText, left, base + width);
        break;
      }
      case BlockKind::Code:
        for (const TextSpan& s : b.spans) {
          ImGui::PushFont(p.code ? p.code : body);
          ImGui::SetCursorPosX(base + indentStep);
          ImGui::TextColored(kCode, "%s", s.text.c_str());
          ImGui::PopFont();
        }
        break;
      case BlockKind::DisplayMath: {
        std::string text;
        for (const TextSpan& s : b.spans) text += s.text;
        const float w = ImGui::CalcTextSize(text.c_str()).x;
        ImGui::Spacing();
        if (w < width) {
          ImGui::SetCursorPosX(base + (width - w) * 0.5f);
          ImGui::TextColored(kMath, "%s", text.c_str());
        } else {
          ImGui::PushTextWrapPos(base + width);
          ImGui::TextColored(kMath, "%s", text.c_str());
          ImGui::PopTextWrapPos();
        }
        ImGui::Spacing();
        break;
      }
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
  const float footer = buttonH + ImGui::GetTextLineHeightWithSpacing() * 2.0f + style.ItemSpacing.y * 3.0f;
  ImGui::BeginChild("##slidetext", ImVec2(0, std::max(h - footer - style.WindowPadding.y * 2.0f, 50.0f)));
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
  const Slide& s = p.deck->slides[static_cast<size_t>(p.index)];
  ImGui::TextColored(kDim, "%d / %d   %s", p.index + 1, p.count(), p.deck->title.c_str());
  ImGui::TextColored(kDim, "Tab controls   N notes%s   F11 full screen", s.notes.empty() ? " (none)" : "");
  ImGui::End();
}

}  // namespace ll::gui
