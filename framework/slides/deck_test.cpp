// Decks: slides split at --- lines (not inside code), titles and GitHub
// anchors, notes, preset blocks inline or by file with the deck's line
// numbers in errors; slide text through md4c; LaTeX as readable text.
#include "slides/deck.h"

#include <gtest/gtest.h>

#include "slides/slide_text.h"
#include "test_support.h"

namespace ll {
namespace {

using testing_support::contains;
using testing_support::errorOf;

const std::string kDeckPath = std::string(LIGHTLAB_DATA_DIR) + "/../slides/test.md";  // resolves ../data/...

TEST(Deck, SplitsAtRulesOutsideCodeAndNamesSlidesLikeGitHub) {
  const Deck d = parseDeck("# Ray casting\n\nintro\n\n---\n\n## Snell's law: refraction\n\n```text\n---\n```\n\n"
                           "---\n\n## Snell's law: refraction\n\nNote: say it twice\nsecond line\n",
                           kDeckPath);
  ASSERT_EQ(d.slides.size(), 3u);
  EXPECT_EQ(d.title, "Ray casting");
  EXPECT_EQ(d.slides[0].anchor, "ray-casting");
  EXPECT_EQ(d.slides[1].anchor, "snells-law-refraction");
  EXPECT_TRUE(contains(d.slides[1].markdown, "```text\n---\n```"));  // a rule inside code stays code
  EXPECT_EQ(d.slides[2].anchor, "snells-law-refraction-1");      // GitHub's suffix for repeats
  EXPECT_EQ(d.slides[2].notes, "say it twice\nsecond line\n");
  EXPECT_FALSE(contains(d.slides[2].markdown, "say it"));
  EXPECT_EQ(d.slides[1].line, 6);
}

TEST(Deck, InlinePresetsNeedNoTagAndResolveAgainstTheDeck) {
  const Deck d = parseDeck("# T\n\n```preset\n{\"description\": \"two\", \"scene\": \"../data/scenes/cornell_box.json\",\n"
                           " \"panes\": [{\"technique\": \"raycast\"}, {\"technique\": \"whitted\"}]}\n```\n",
                           kDeckPath);
  ASSERT_TRUE(d.slides[0].preset);
  const SlidePreset& p = *d.slides[0].preset;
  EXPECT_EQ(p.line, 3);
  EXPECT_EQ(p.source, "inline");
  EXPECT_EQ(p.preset.description, "two");
  EXPECT_EQ(p.preset.panes[1].technique, "whitted");
  EXPECT_TRUE(contains(p.preset.scene, "data/scenes/cornell_box.json"));
  EXPECT_TRUE(contains(d.slides[0].markdown, kFigureMarker));
}

TEST(Deck, PresetFilesResolveAgainstTheDeck) {
  const Deck d = parseDeck("# T\n```preset\n../data/presets/bvh_cost.json\n```\n", kDeckPath);
  ASSERT_TRUE(d.slides[0].preset);
  EXPECT_EQ(d.slides[0].preset->source, "../data/presets/bvh_cost.json");
  EXPECT_EQ(d.slides[0].preset->preset.panes[0].view, "nodes");
}

TEST(Deck, ErrorsNameTheDeckLineAndWhatIsAllowed) {
  const auto err = [](const std::string& text) { return errorOf([&] { parseDeck(text, "d.md"); }); };
  EXPECT_TRUE(contains(err("# A\n\n```preset\n{\"scene\": \"x.json\",\n \"pane\": []}\n```\n"),
                       "d.md:5:2: unknown key 'pane' in preset (allowed: "));
  EXPECT_TRUE(contains(err("# A\n```preset\n{\"scene\": \"x.json\"\n"), "d.md:2: unterminated preset block"));
  EXPECT_TRUE(contains(err("# A\n```preset fast\nx.json\n```\n"), "d.md:2: unknown preset block option 'fast'"));
  EXPECT_TRUE(contains(err("# A\n```preset\nnope.json\n```\n"), "d.md:3: preset file 'nope.json' not found"));
  EXPECT_TRUE(contains(err("# A\n```preset\n```\n"), "d.md:2: empty preset block"));
  EXPECT_TRUE(contains(err("\n\n---\n\n"), "d.md: no slides"));
  EXPECT_TRUE(contains(errorOf([] { loadDeck("/nonexistent/deck.md"); }), "/nonexistent/deck.md: no such slide deck"));
}

TEST(SlideText, HeadingsBulletsCodeAndMath) {
  const auto blocks = slideText("## Title\n\n- one `code` $\\rho$\n  - nested\n\n$$B_i = E_i$$\n\n1. first\n");
  ASSERT_GE(blocks.size(), 5u);
  EXPECT_EQ(blocks[0].kind, BlockKind::Heading);
  EXPECT_EQ(blocks[0].level, 2);
  EXPECT_EQ(blocks[1].kind, BlockKind::ListItem);
  EXPECT_EQ(blocks[1].level, 1);
  ASSERT_GE(blocks[1].spans.size(), 4u);
  EXPECT_EQ(blocks[1].spans[1].style, SpanStyle::Code);
  EXPECT_EQ(blocks[1].spans[1].text, "code");
  EXPECT_EQ(blocks[1].spans[3].style, SpanStyle::Math);
  EXPECT_EQ(blocks[1].spans[3].text, "ρ");
  EXPECT_EQ(blocks[2].level, 2);  // the nested bullet
  EXPECT_EQ(blocks[3].kind, BlockKind::DisplayMath);
  EXPECT_EQ(blocks[3].spans[0].text, "Bᵢ = Eᵢ");
  EXPECT_EQ(blocks[4].marker, "1.");
}

TEST(SlideText, LatexBecomesReadableText) {
  EXPECT_EQ(mathAsText("\\frac{a}{b}"), "a/b");
  EXPECT_EQ(mathAsText("x^2 + F_{ij}"), "x² + Fᵢⱼ");
  EXPECT_EQ(mathAsText("\\int_\\Omega L \\cos^2\\theta"), "∫_Ω L cos²θ");
  EXPECT_EQ(mathAsText("\\frac{l + v}{\\lVert l + v \\rVert}"), "(l + v)/‖l + v‖");
  EXPECT_EQ(mathAsText("\\mathrm{W\\,m^{-2}}"), "W m⁻²");
}

}  // namespace
}  // namespace ll
