#include "slides/deck.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.h"
#include "core/files.h"

namespace ll {

namespace fs = std::filesystem;

namespace {

std::string trimmed(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

// "```lang" or "~~~lang" (up to 3 spaces of indent): the fence, else "".
std::string fenceOf(const std::string& line) {
  const size_t a = line.find_first_not_of(' ');
  if (a == std::string::npos || a > 3) return "";
  const char c = line[a];
  if (c != '`' && c != '~') return "";
  size_t n = 0;
  while (a + n < line.size() && line[a + n] == c) ++n;
  return n >= 3 ? line.substr(a, n) : "";
}

struct DeckParser {
  const std::string& path;
  std::string dir;
  Deck deck;
  std::map<std::string, int> anchors;  // slug -> times used

  [[noreturn]] void fail(int line, const std::string& message) const {
    throwUserError(path + ":" + std::to_string(line) + ": " + message);
  }

  // The preset's scene must exist: a deck that names a missing scene fails when it loads, not in class.
  SlidePreset checked(SlidePreset p) const {
    if (!fs::is_regular_file(p.preset.scene))
      fail(p.line + 1, "the preset's scene '" + p.preset.scene + "' not found");
    return p;
  }

  SlidePreset parseBlock(int fenceLine, const std::vector<std::string>& body) const {
    SlidePreset p;
    p.line = fenceLine;
    std::string first;
    int count = 0;
    for (const std::string& l : body)
      if (!trimmed(l).empty()) {
        if (first.empty()) first = trimmed(l);
        ++count;
      }
    if (count == 0)
      fail(fenceLine, "empty preset block (allowed: a JSON view preset, or one line naming a preset file)");
    if (first[0] == '{') {
      // Blank lines before the JSON keep its line numbers those of the deck.
      std::string text(static_cast<size_t>(fenceLine), '\n');
      for (const std::string& l : body) text += l + "\n";
      p.source = "inline";
      p.preset = parsePreset(text, path, dir, true);
      return checked(p);
    }
    if (count > 1)
      fail(fenceLine, "a preset block holds a JSON view preset or one preset file path, not " +
                          std::to_string(count) + " lines");
    p.source = first;
    const fs::path file = fs::path(dir) / first;
    if (!fs::is_regular_file(file))
      fail(fenceLine + 1, "preset file '" + first + "' not found (looked for " + file.lexically_normal().string() + ")");
    p.preset = loadPreset(file.lexically_normal().string());
    return checked(p);
  }

  void finishSlide(Slide& s) {
    if (s.title.empty() && trimmed(s.markdown).empty() && !s.preset) return;  // nothing between two rules
    std::string slug = s.title.empty() ? "slide-" + std::to_string(deck.slides.size() + 1) : headingSlug(s.title);
    const int used = anchors[slug]++;
    if (used > 0) slug += "-" + std::to_string(used);
    s.anchor = slug;
    deck.slides.push_back(std::move(s));
  }

  void parse(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    Slide slide;
    slide.line = 1;
    bool inNotes = false;
    for (size_t i = 0; i < lines.size(); ++i) {
      const std::string& line = lines[i];
      const int lineNo = static_cast<int>(i) + 1;
      const std::string fence = fenceOf(line);
      if (!fence.empty()) {  // a fenced block: copied whole, or taken as the slide's preset
        const std::string info = trimmed(trimmed(line).substr(fence.size()));
        const bool isPreset = info == "preset" || info.rfind("preset ", 0) == 0;
        if (isPreset && info != "preset")
          fail(lineNo, "unknown preset block option '" + trimmed(info.substr(6)) + "' (allowed: none; write ```preset)");
        std::vector<std::string> body;
        size_t j = i + 1;
        for (; j < lines.size(); ++j) {
          const std::string close = fenceOf(lines[j]);
          if (!close.empty() && close[0] == fence[0] && close.size() >= fence.size() &&
              trimmed(lines[j]) == close)
            break;
          body.push_back(lines[j]);
        }
        if (j == lines.size())
          fail(lineNo, std::string("unterminated ") + (isPreset ? "preset" : "fenced") + " block (close it with " +
                           fence + ")");
        if (isPreset) {
          if (inNotes) fail(lineNo, "a preset block inside the speaker notes (put it above the Note: line)");
          if (slide.preset)
            fail(lineNo, "a second preset block in the slide of line " + std::to_string(slide.line) +
                             " (one per slide; split the slide with ---)");
          slide.preset = parseBlock(lineNo, body);
          slide.markdown += std::string(kFigureMarker) + "\n";
        } else {
          std::string& out = inNotes ? slide.notes : slide.markdown;
          for (size_t k = i; k <= j; ++k) out += lines[k] + "\n";
        }
        i = j;
        continue;
      }
      if (trimmed(line) == "---") {
        finishSlide(slide);
        slide = Slide{};
        slide.line = lineNo + 1;
        inNotes = false;
        continue;
      }
      if (!inNotes && (line.rfind("Note:", 0) == 0 || line.rfind("Notes:", 0) == 0)) {
        inNotes = true;
        slide.notes += trimmed(line.substr(line.find(':') + 1)) + "\n";
        continue;
      }
      if (inNotes) {
        slide.notes += line + "\n";
        continue;
      }
      if (slide.title.empty() && line.rfind('#', 0) == 0) {
        const size_t a = line.find_first_not_of('#');
        if (a != std::string::npos && a <= 6 && (line[a] == ' ' || line[a] == '\t')) slide.title = trimmed(line.substr(a));
      }
      slide.markdown += line + "\n";
    }
    finishSlide(slide);
    if (deck.slides.empty()) throwUserError(path + ": no slides (write Markdown, slides separated by --- lines)");
    deck.title = deck.slides.front().title;
  }
};

}  // namespace

std::string headingSlug(const std::string& heading) {
  std::string slug;
  for (const char c : heading) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '-' || c == '_' || u >= 0x80)
      slug += static_cast<char>(std::tolower(u));
    else if (c == ' ')
      slug += '-';
  }
  return slug;
}

Deck parseDeck(const std::string& text, const std::string& path) {
  DeckParser parser{path, fs::path(path).parent_path().string(), {}, {}};
  parser.deck.path = path;
  parser.parse(text);
  return std::move(parser.deck);
}

Deck loadDeck(const std::string& path) {
  return parseDeck(readTextFile(path, "slide deck"), path);
}

}  // namespace ll
