// Every preset named in every deck under slides/ loads and renders headless
// (tiny: 40 pixels wide, one pass): a finite, non-uniform picture, and in the
// solution build no student stub ran; every slide has speaker notes; code lines
// fit the presenter's slide panel. One test per deck.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "preset/preset_render.h"
#include "slides/deck.h"

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

GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(SlideDeck);
INSTANTIATE_TEST_SUITE_P(Slides, SlideDeck, testing::ValuesIn(deckNames()),
                         [](const testing::TestParamInfo<std::string>& deck) { return deck.param; });

}  // namespace
}  // namespace ll
