// A lecture deck: one Markdown file, slides separated by lines that hold
// only `---`. A slide may name its demo in one fenced block whose info string
// is `preset`: either a JSON view preset written inline (the
// "lightlab_preset" tag may be left out) or one line naming a preset file;
// relative paths (the file, and an inline preset's scene) resolve against the
// deck's folder. A line `Note:` starts the slide's speaker notes. The format
// is documented in slides/README.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "preset/view_preset.h"

namespace ll {

// In a slide's Markdown, the line that stands where its preset block was.
inline constexpr const char* kFigureMarker = "<!-- lightlab:figure -->";

struct SlidePreset {
  int line = 0;        // 1-based line of the opening fence in the deck
  std::string source;  // the preset file as written in the block, or "inline"
  ViewPreset preset;
};

struct Slide {
  int line = 0;          // 1-based line of the slide's first line in the deck
  std::string title;     // text of its first heading ("" if none)
  std::string anchor;    // GitHub-style slug of the title, unique in the deck (slide-N if untitled)
  std::string markdown;  // the slide without its notes; kFigureMarker replaces the preset block
  std::string notes;     // speaker notes (Markdown), "" if none
  std::optional<SlidePreset> preset;
};

struct Deck {
  std::string path;   // as given
  std::string title;  // the first slide's title
  std::vector<Slide> slides;
};

// Reads and validates a deck and every preset it names. Throws UserError
// naming deck:line (or preset:line:col) and what is allowed.
Deck loadDeck(const std::string& path);
Deck parseDeck(const std::string& text, const std::string& path);

// GitHub's heading anchor: lower case, punctuation dropped, spaces as '-'.
std::string headingSlug(const std::string& heading);

}  // namespace ll
