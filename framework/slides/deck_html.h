// One deck as one self-contained HTML page: every slide's Markdown through
// md4c's HTML renderer, its figure embedded as a PNG data URI, and the
// equations typeset in the browser by Debian's KaTeX, inlined with its fonts
// as data URIs, so the page needs no network. Arrow keys, PageUp/PageDown and
// space step through the slides; N shows the speaker notes.
#pragma once

#include <string>
#include <vector>

#include "slides/deck.h"

namespace ll {

struct SlideFigure {
  std::string png;      // PNG file bytes; empty if the figure failed or the slide has none
  std::string caption;  // the preset's description
  std::string error;    // why it failed ("" = fine)
  int width = 0, height = 0;  // CSS pixels it is shown at (0 = the PNG's own size); the PNG may be 2x
};

// `figures` has one entry per slide. `katexDir` holds katex.min.js,
// katex.min.css and fonts/*.woff2. Throws UserError if KaTeX is missing.
std::string deckHtml(const Deck& deck, const std::vector<SlideFigure>& figures, const std::string& katexDir);

// The id of a slide's figure image in the page: "fig-<slide anchor>".
std::string figureId(const Slide& slide);

}  // namespace ll
