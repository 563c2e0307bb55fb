// Every character a deck puts on screen has a glyph in the presenter's fonts:
// a character outside their ranges is drawn as "?" from the back of the hall
// ("?idák's correction").
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "gui/slide_panel.h"
#include "slides/deck.h"
#include "slides/slide_text.h"

namespace ll::gui {
namespace {

namespace fs = std::filesystem;

bool inRanges(char32_t c) {
  for (const unsigned short* r = slideGlyphRanges(); r[0] != 0; r += 2)
    if (c >= r[0] && c <= r[1]) return true;
  return false;
}

// The code points of UTF-8 text (invalid bytes as U+FFFD).
std::u32string codePoints(const std::string& s) {
  std::u32string out;
  for (size_t i = 0; i < s.size();) {
    const auto b = static_cast<unsigned char>(s[i]);
    const int n = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xE ? 3 : (b >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || i + static_cast<size_t>(n) > s.size()) {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    char32_t c = n == 1 ? b : b & (0xFF >> (n + 1));
    for (int k = 1; k < n; ++k) c = (c << 6) | (static_cast<unsigned char>(s[i + static_cast<size_t>(k)]) & 0x3F);
    out.push_back(c);
    i += static_cast<size_t>(n);
  }
  return out;
}

TEST(SlideGlyphs, EveryCharacterOfEveryDeckHasAGlyph) {
  const fs::path dir = fs::path(LIGHTLAB_DATA_DIR) / ".." / "slides";
  if (!fs::is_directory(dir)) GTEST_SKIP() << "no decks in this tree";
  int decks = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".md" || e.path().filename() == "README.md") continue;
    ++decks;
    const Deck deck = loadDeck(e.path().string());
    for (const Slide& slide : deck.slides)
      for (const std::string* md : {&slide.markdown, &slide.notes})
        for (const TextBlock& block : slideText(*md))
          for (const TextSpan& span : block.spans)
            for (const char32_t c : codePoints(span.text))
              EXPECT_TRUE(c == '\n' || c == '\t' || inRanges(c))
                  << e.path().filename().string() << " (" << slide.anchor << "): U+" << std::hex
                  << static_cast<unsigned>(c) << " in \"" << span.text << "\" has no glyph in the slide fonts";
  }
  EXPECT_GT(decks, 0);
}

}  // namespace
}  // namespace ll::gui
