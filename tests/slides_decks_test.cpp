// Every preset named in every deck under slides/ loads and renders headless
// (tiny: 40 pixels wide, one pass): a finite, non-uniform picture, and in the
// solution build no student stub ran; every slide has speaker notes; code lines
// and formulas fit the presenter's slide panel. One test per deck.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <gtest/gtest.h>
#include <stb_truetype.h>

#include "preset/preset_render.h"
#include "slides/deck.h"
#include "slides/slide_text.h"

namespace ll {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> deckNames() {
  std::vector<std::string> names;
  const fs::path dir = fs::path(LIGHTLAB_DATA_DIR) / ".." / "slides";
  if (!fs::is_directory(dir)) return names;  // a tree without decks: nothing to instantiate
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".md" && e.path().filename() != "README.md") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

class SlideDeck : public testing::TestWithParam<std::string> {};

TEST_P(SlideDeck, EveryPresetLoadsAndRendersHeadless) {
  const fs::path path = (fs::path(LIGHTLAB_DATA_DIR) / ".." / "slides" / (GetParam() + ".md")).lexically_normal();
  const Deck deck = loadDeck(path.string());
  int presets = 0;
  for (const Slide& slide : deck.slides) {
    if (!slide.preset) continue;
    ++presets;
    SCOPED_TRACE(path.string() + ":" + std::to_string(slide.preset->line) + " (" + slide.anchor + ")");
    if (presetNeedsGpu(slide.preset->preset)) continue;  // no GL context in unit tests
    const PresetFigure f = renderPresetFigure(slide.preset->preset, {40, 1});
    ASSERT_FALSE(f.image.empty());
    EXPECT_EQ(f.paneWidth, 40);
    float lo = 1e30f, hi = -1e30f;
    for (const Rgb& c : f.image.pixels()) {
      ASSERT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b));
      lo = std::min(lo, c.r + c.g + c.b);
      hi = std::max(hi, c.r + c.g + c.b);
    }
    // The difference of two equal renders is rightly uniform black.
    if (slide.preset->preset.compare.mode != CompareMode::Difference) {
      EXPECT_GT(hi - lo, 0.01f) << "a uniform picture";
    }
    if (LIGHTLAB_SOLUTION) {
      EXPECT_TRUE(f.missingTasks.empty()) << f.missingTasks.begin()->first;
    }
  }
  EXPECT_GT(presets, 0) << "a deck without a single figure";
}

// The lecturer's notes: every slide has some, written out (not a placeholder line).
TEST_P(SlideDeck, EverySlideHasSpeakerNotes) {
  const fs::path path = (fs::path(LIGHTLAB_DATA_DIR) / ".." / "slides" / (GetParam() + ".md")).lexically_normal();
  const Deck deck = loadDeck(path.string());
  for (const Slide& slide : deck.slides) {
    SCOPED_TRACE(path.string() + " (" + slide.anchor + ")");
    EXPECT_GE(slide.notes.size(), 120u) << "no speaker notes (a `Note:` line and what follows it)";
  }
}

// Code on a slide is read from the back of the hall: presenter mode shrinks a
// code block to at most 0.75 of its size to fit the slide panel, then scrolls it
// sideways, hiding the ends of its lines. At 1600x900 and UI scale 2 (a small
// projector at the lecture-hall setting) the panel shows 47 columns at 0.75,
// one less when the slide scrolls; so no line of a code block is longer than 46.
TEST_P(SlideDeck, EveryCodeLineFitsThePresenterPanel) {
  constexpr size_t kColumns = 46;
  const fs::path path = (fs::path(LIGHTLAB_DATA_DIR) / ".." / "slides" / (GetParam() + ".md")).lexically_normal();
  const Deck deck = loadDeck(path.string());
  for (const Slide& slide : deck.slides) {
    std::istringstream in(slide.markdown);
    std::string line;
    bool code = false;
    for (int n = 0; std::getline(in, line); ++n) {
      if (line.rfind("```", 0) == 0) {
        code = !code;
        continue;
      }
      // Columns are code points: count the bytes that do not continue a UTF-8 sequence.
      const auto columns = static_cast<size_t>(
          std::count_if(line.begin(), line.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
      if (code) {
        EXPECT_LE(columns, kColumns) << path.string() << " (" << slide.anchor << "), line " << n + 1
                                     << " of the slide: " << line;
      }
    }
  }
}

// Text widths as the presenter measures them: the sum of DejaVu Sans' advances at `pixels` (ImGui
// neither kerns nor snaps them), a script at 0.7 of the size.
class PresenterFont {
 public:
  explicit PresenterFont(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    bytes_.assign(std::istreambuf_iterator<char>(in), {});
    ok_ = !bytes_.empty() && stbtt_InitFont(&font_, bytes_.data(), stbtt_GetFontOffsetForIndex(bytes_.data(), 0));
  }
  bool ok() const { return ok_; }
  float width(const std::string& utf8, float pixels) const {
    const float scale = stbtt_ScaleForPixelHeight(&font_, pixels);
    float w = 0.0f;
    for (size_t i = 0; i < utf8.size();) {  // decode UTF-8
      const auto c = static_cast<unsigned char>(utf8[i]);
      const int n = c < 0x80 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
      int cp = n == 1 ? c : c & (0x3F >> (n - 1));
      for (int k = 1; k < n && i + k < utf8.size(); ++k) cp = (cp << 6) | (static_cast<unsigned char>(utf8[i + k]) & 0x3F);
      i += static_cast<size_t>(n);
      int advance = 0, bearing = 0;
      stbtt_GetCodepointHMetrics(&font_, cp, &advance, &bearing);
      w += static_cast<float>(advance) * scale;
    }
    return w;
  }

 private:
  std::vector<unsigned char> bytes_;
  stbtt_fontinfo font_{};
  bool ok_ = false;
};

// Equations are read from the back of the hall too. At 1600x900 and UI scale 2 the presenter sets
// slide text in 30-pixel DejaVu Sans (15 px x 2) in a column 584 px wide when the slide scrolls
// (the slide panel, 0.42 of the window, less 2 x 16 px of padding and 2 x 28 px for the scrollbar),
// a list item's 42 px (1.4 em) per level narrower. Every line of every formula on a slide --
// display equations and those in the text -- is drawn at 0.9 of the full size or more: wrapSpans
// breaks a formula where it does not fit and shrinks a part only that little. A part that must
// shrink further reads small on a projector: split the equation in the deck, or say less in it.
TEST_P(SlideDeck, EveryFormulaFitsThePresenterPanelNearlyFullSize) {
  constexpr float kPixels = 30.0f, kColumn = 584.0f, kIndent = 42.0f;
  const PresenterFont font("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf");
  if (!font.ok()) GTEST_SKIP() << "no DejaVu Sans (Debian fonts-dejavu-core): the presenter's font";
  const MeasureText measure = [&](const std::string& text, const TextSpan& span) {
    return font.width(text, kPixels * (span.script != 0 ? 0.7f : 1.0f));
  };
  const fs::path path = (fs::path(LIGHTLAB_DATA_DIR) / ".." / "slides" / (GetParam() + ".md")).lexically_normal();
  const Deck deck = loadDeck(path.string());
  for (const Slide& slide : deck.slides)
    for (const TextBlock& block : slideText(slide.markdown)) {
      if (block.kind == BlockKind::Heading || block.kind == BlockKind::Code) continue;  // headings have no formulas
      const float indent =
          block.kind == BlockKind::ListItem || block.kind == BlockKind::Paragraph ? kIndent * static_cast<float>(block.level) : 0.0f;
      for (const LaidLine& line : wrapSpans(block.spans, kColumn - indent, measure)) {
        std::string text;
        for (const LaidPiece& piece : line.pieces) text += piece.text + " ";
        EXPECT_GE(line.scale, 0.9f) << path.string() << " (" << slide.anchor << "): shrunk to " << line.scale
                                    << " on the presenter's slide panel: " << text;
      }
    }
}

GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(SlideDeck);
INSTANTIATE_TEST_SUITE_P(Slides, SlideDeck, testing::ValuesIn(deckNames()),
                         [](const testing::TestParamInfo<std::string>& deck) { return deck.param; });

}  // namespace
}  // namespace ll
