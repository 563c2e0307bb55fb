#include "slides/deck_html.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <md4c-html.h>

#include "core/base64.h"
#include "core/error.h"
#include "core/markup.h"

namespace ll {

namespace fs = std::filesystem;

namespace {

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throwUserError(path.string() + ": cannot read (is Debian's libjs-katex installed?)");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string markdownHtml(const std::string& markdown) {
  std::string html;
  md_html(markdown.data(), static_cast<MD_SIZE>(markdown.size()),
          [](const MD_CHAR* text, MD_SIZE size, void* out) { static_cast<std::string*>(out)->append(text, size); },
          &html, MD_DIALECT_GITHUB | MD_FLAG_LATEXMATHSPANS, 0);
  return html;
}

// KaTeX's stylesheet with each font's woff2 inlined and the woff/ttf fallbacks dropped.
std::string katexCss(const fs::path& dir) {
  const std::string css = readFile(dir / "katex.min.css");
  static const std::regex font(R"(url\(fonts/([A-Za-z0-9_-]+)\.(woff2|woff|ttf)\) format\(['"][a-z0-9]+['"]\),?)");
  std::string out;
  auto last = css.cbegin();
  for (std::sregex_iterator it(css.begin(), css.end(), font), end; it != end; ++it) {
    out.append(last, (*it)[0].first);
    if ((*it)[2] == "woff2")
      out += "url(data:font/woff2;base64," + base64(readFile(dir / "fonts" / ((*it)[1].str() + ".woff2"))) +
             ") format('woff2')";
    last = (*it)[0].second;
  }
  out.append(last, css.cend());
  return out;
}

// Text beside the figure; a slide whose equation, code or table is too wide for its column puts the
// figure under the text instead (class "stacked", set by kScript), and what is still too wide scrolls
// sideways inside its own box: text, equations and figures never overlap.
constexpr const char* kStyle = R"(
body { margin: 0; background: #2b2b30; font: 22px/1.4 "DejaVu Sans", "Helvetica Neue", Arial, sans-serif; color: #1d1d1f; }
section.slide { box-sizing: border-box; width: min(1280px, 96vw); min-height: min(720px, 54vw); margin: 2vw auto;
  padding: 36px 48px; background: #fff; border-radius: 6px; display: flex; gap: 36px; align-items: flex-start; }
section.slide .text { flex: 1 1 0; min-width: 0; }
section.slide figure { flex: 0 1 auto; max-width: 50%; margin: 0; text-align: center; }
section.slide figure img { display: block; max-width: 100%; height: auto; margin: 0 auto; image-rendering: auto;
  border: 1px solid #ccc; box-sizing: border-box; }
section.slide.stacked { flex-direction: column; align-items: stretch; }
section.slide.stacked figure { max-width: 100%; align-self: center; }
section.slide figcaption { font-size: 16px; color: #555; margin-top: 6px; overflow-wrap: anywhere; }
section.slide .failed { border: 2px dashed #c00; color: #c00; padding: 20px; font-size: 16px; }
h1 { font-size: 44px; margin: 0 0 18px; } h2 { font-size: 34px; margin: 0 0 16px; color: #123d6a; }
h1, h2, h3, p, li { overflow-wrap: break-word; }
code { background: #eef1f5; padding: 1px 5px; border-radius: 3px; font-size: 0.9em; }
pre { max-width: 100%; overflow-x: auto; } pre code { display: block; padding: 10px; white-space: pre; }
table { border-collapse: collapse; font-size: 18px; display: block; max-width: 100%; overflow-x: auto; }
td, th { border: 1px solid #bbb; padding: 4px 10px; }
aside.notes { display: none; margin-top: 18px; padding: 10px; background: #fff8d8; font-size: 17px; }
body.show-notes aside.notes { display: block; }
.counter { float: right; color: #888; font-size: 15px; }
x-equation[type=display] { display: block; text-align: center; margin: 12px 0; max-width: 100%;
  overflow-x: auto; overflow-y: hidden; padding: 2px 0; }
x-equation[type=display] .katex-display { margin: 0; }
@media print { body { background: #fff; } section.slide { break-after: page; margin: 0 auto; } }
)";

// Typesets md4c's <x-equation> elements, lays out the slides whose content is too wide for a column
// (figure under the text; an equation still too wide shrinks to 60 %, then scrolls); keys step
// through the slides.
constexpr const char* kScript = R"(
document.querySelectorAll('x-equation').forEach(function (e) {
  katex.render(e.textContent, e, {displayMode: e.getAttribute('type') === 'display', throwOnError: false});
});
(function () {
  function tooWide(e) { return e.scrollWidth > e.clientWidth + 1; }
  function fit() {
    var wide = 'x-equation[type=display], pre, table';
    document.querySelectorAll('x-equation[type=display]').forEach(function (e) { e.style.fontSize = ''; });
    document.querySelectorAll('section.slide').forEach(function (s) {
      s.classList.remove('stacked');
      if (s.querySelector('figure') && Array.prototype.some.call(s.querySelectorAll(wide), tooWide))
        s.classList.add('stacked');
    });
    document.querySelectorAll('x-equation[type=display]').forEach(function (e) {
      if (tooWide(e)) e.style.fontSize = Math.max(60, Math.floor(100 * e.clientWidth / e.scrollWidth)) + '%';
    });
    document.body.setAttribute('data-laid-out', '1');
  }
  fit();
  window.addEventListener('resize', fit);
  if (document.fonts && document.fonts.ready) document.fonts.ready.then(fit);
})();
(function () {
  var slides = Array.prototype.slice.call(document.querySelectorAll('section.slide'));
  function current() {
    var best = 0;
    slides.forEach(function (s, i) { if (s.getBoundingClientRect().top < window.innerHeight / 3) best = i; });
    return best;
  }
  function go(i) { i = Math.max(0, Math.min(slides.length - 1, i)); slides[i].scrollIntoView({block: 'start'});
                   history.replaceState(null, '', '#' + slides[i].id); }
  document.addEventListener('keydown', function (e) {
    if (['ArrowRight', 'ArrowDown', 'PageDown', ' '].indexOf(e.key) >= 0) { go(current() + 1); e.preventDefault(); }
    else if (['ArrowLeft', 'ArrowUp', 'PageUp', 'Backspace'].indexOf(e.key) >= 0) { go(current() - 1); e.preventDefault(); }
    else if (e.key === 'Home') go(0); else if (e.key === 'End') go(slides.length - 1);
    else if (e.key === 'n' || e.key === 'N') document.body.classList.toggle('show-notes');
  });
})();
)";

}  // namespace

std::string figureId(const Slide& slide) { return "fig-" + slide.anchor; }

std::string deckHtml(const Deck& deck, const std::vector<SlideFigure>& figures, const std::string& katexDir) {
  const fs::path katex(katexDir);
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
    << "<meta name=\"generator\" content=\"lightlab slides build\">\n"
    << "<title>" << escapeMarkup(deck.title.empty() ? deck.path : deck.title) << "</title>\n"
    << "<style>" << katexCss(katex) << "</style>\n<style>" << kStyle << "</style>\n</head><body>\n";
  const std::string marker = kFigureMarker;
  for (size_t i = 0; i < deck.slides.size(); ++i) {
    const Slide& s = deck.slides[i];
    const SlideFigure& f = figures.at(i);
    std::string figure;
    if (s.preset) {
      std::ostringstream fig;
      fig << "<figure data-preset=\"" << escapeMarkup(s.preset->source) << "\" data-line=\"" << s.preset->line << "\">";
      if (!f.error.empty() || f.png.empty())
        fig << "<div class=\"failed figure-failed\">figure failed: " << escapeMarkup(f.error) << "</div>";
      else
        fig << "<img id=\"" << figureId(s) << "\" alt=\"" << escapeMarkup(f.caption) << "\" src=\"data:image/png;base64,"
            << base64(f.png) << "\""
            << (f.width > 0 && f.height > 0
                    ? " width=\"" + std::to_string(f.width) + "\" height=\"" + std::to_string(f.height) + "\""
                    : std::string())
            << ">";
      if (!f.caption.empty()) fig << "<figcaption>" << escapeMarkup(f.caption) << "</figcaption>";
      fig << "</figure>";
      figure = fig.str();
    }
    std::string text = markdownHtml(s.markdown);
    const size_t at = text.find(marker);  // the figure goes beside the text, not inside it
    if (at != std::string::npos) text.erase(at, marker.size());
    h << "<section class=\"slide\" id=\"" << s.anchor << "\"><div class=\"text\"><span class=\"counter\">" << i + 1
      << " / " << deck.slides.size() << "</span>\n"
      << text;
    if (!s.notes.empty()) h << "<aside class=\"notes\">" << markdownHtml(s.notes) << "</aside>";
    h << "</div>" << figure << "</section>\n";
  }
  h << "<script>" << readFile(katex / "katex.min.js") << "</script>\n<script>" << kScript << "</script>\n</body></html>\n";
  return h.str();
}

}  // namespace ll
