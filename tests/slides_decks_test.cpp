// Every preset named in every deck under slides/ loads and renders headless
// (tiny: 40 pixels wide, one pass): a finite, non-uniform picture, and in the
// solution build no student stub ran; every slide has speaker notes. One test per deck.
#include <algorithm>
#include <cmath>
#include <filesystem>

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

GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(SlideDeck);
INSTANTIATE_TEST_SUITE_P(Slides, SlideDeck, testing::ValuesIn(deckNames()),
                         [](const testing::TestParamInfo<std::string>& deck) { return deck.param; });

}  // namespace
}  // namespace ll
