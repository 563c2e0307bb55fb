// lightlab slides build [DECKS...] --out DIR [--max-width W] [--max-spp N]
// lightlab slides check [DECKS...]
// `build` renders every deck (default: slides/*.md) into DIR/<deck>.html, one
// self-contained page each: figures rendered now from the slides' presets,
// equations typeset offline. DIR/figures.json lists every figure (deck,
// slide, preset, size, time, error). Exits non-zero if any figure failed.
// `check` only loads the decks and validates every preset they name.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "core/error.h"
#include "core/progress.h"
#ifdef LIGHTLAB_HAVE_GUI
#include "gpu/offscreen_gl.h"
#endif
#include "slides/deck_html.h"
#include "slides/slide_figures.h"

namespace ll::cli {

namespace fs = std::filesystem;

namespace {

struct SlidesOptions {
  std::vector<std::string> decks;
  std::string out;
  FigureLimits limits;
};

// slides/*.md (not README.md) under the working directory, else under the source tree.
std::vector<std::string> defaultDecks() {
  for (const fs::path& dir : {fs::path("slides"), fs::path(LIGHTLAB_SOURCE_DIR) / "slides"}) {
    if (!fs::is_directory(dir)) continue;
    std::vector<std::string> decks;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".md" && e.path().filename() != "README.md") decks.push_back(e.path().string());
    std::sort(decks.begin(), decks.end());
    if (!decks.empty()) return decks;
  }
  throwUserError("no slide decks found in slides/; name them: lightlab slides build DECK.md --out DIR");
}

std::vector<Deck> loadDecks(const std::vector<std::string>& paths) {
  std::vector<Deck> decks;
  for (const std::string& p : paths.empty() ? defaultDecks() : paths) decks.push_back(loadDeck(p));
  return decks;
}

void build(const SlidesOptions& o, const GlobalOptions& global) {
  const std::vector<Deck> decks = loadDecks(o.decks);  // every deck validated before any render
  std::error_code ec;
  fs::create_directories(o.out, ec);
  if (!fs::is_directory(o.out)) throwUserError(o.out + ": cannot create output folder");
#ifdef LIGHTLAB_HAVE_GUI
  for (const Deck& d : decks)
    for (const Slide& s : d.slides)
      if (s.preset && presetNeedsGpu(s.preset->preset)) gpu::OffscreenGl::createForCommandLine();
#endif
  nlohmann::json manifest = nlohmann::json::array();
  int figureCount = 0, failed = 0;
  std::string firstFailure;
  for (const Deck& deck : decks) {
    const auto figures = static_cast<double>(
        std::count_if(deck.slides.begin(), deck.slides.end(), [](const Slide& s) { return s.preset.has_value(); }));
    const std::string stem = fs::path(deck.path).stem().string();
    ProgressBar bar("slides " + stem, std::max(figures, 1.0), global.quiet);
    std::vector<FigureReport> reports;
    const std::vector<SlideFigure> rendered =
        renderDeckFigures(deck, o.limits, [&](double done) { bar.update(done); }, &reports);
    bar.finish();
    const fs::path page = fs::path(o.out) / (stem + ".html");
    std::ofstream out(page, std::ios::binary);
    if (!out) throwUserError(page.string() + ": cannot write");
    out << deckHtml(deck, rendered, LIGHTLAB_KATEX_DIR);
    for (size_t i = 0; i < deck.slides.size(); ++i) {
      const Slide& s = deck.slides[i];
      if (!s.preset) continue;
      ++figureCount;
      const SlideFigure& f = rendered[i];
      const FigureReport& r = reports[i];
      if (!f.error.empty()) {
        ++failed;
        if (firstFailure.empty()) firstFailure = f.error;
      }
      manifest.push_back({{"deck", deck.path},
                          {"html", page.string()},
                          {"slide", i + 1},
                          {"anchor", s.anchor},
                          {"line", s.preset->line},
                          {"preset", s.preset->source},
                          {"id", figureId(s)},
                          {"width", r.width},
                          {"height", r.height},
                          {"png_bytes", f.png.size()},
                          {"seconds", r.seconds},
                          {"missing_tasks", r.missingTasks},
                          {"error", f.error}});
    }
    std::printf("wrote %s (%zu slides, %.0f figures)\n", page.string().c_str(), deck.slides.size(), figures);
  }
  const fs::path manifestPath = fs::path(o.out) / "figures.json";
  std::ofstream(manifestPath) << manifest.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  if (failed > 0)
    throwUserError(std::to_string(failed) + " of " + std::to_string(figureCount) + " figures failed (first: " +
                   firstFailure + "); see " + manifestPath.string());
}

}  // namespace

Command addSlidesCommand(CLI::App& app, const GlobalOptions& global) {
  auto o = std::make_shared<SlidesOptions>();
  CLI::App* cmd = app.add_subcommand("slides", "Lecture decks: build self-contained HTML pages, or check them");
  cmd->require_subcommand(1);
  CLI::App* buildCmd = cmd->add_subcommand("build", "Render decks (default: slides/*.md) into DIR/<deck>.html");
  buildCmd->add_option("decks", o->decks, "Markdown decks (default: every slides/*.md)");
  buildCmd->add_option("--out", o->out, "Output folder")->required();
  buildCmd->add_option("--max-width", o->limits.maxWidth, "Render figures at most this wide per pane (0 = as the preset says)")
      ->check(CLI::Range(0, 16384));
  buildCmd->add_option("--max-spp", o->limits.maxSpp, "At most this many passes per pane (0 = as the preset says)")
      ->check(CLI::Range(0, 1 << 16));
  CLI::App* checkCmd = cmd->add_subcommand("check", "Load decks and validate every preset they name (no rendering)");
  checkCmd->add_option("decks", o->decks, "Markdown decks (default: every slides/*.md)");
  return [o, &global, buildCmd]() {
    if (buildCmd->parsed()) {
      build(*o, global);
      return;
    }
    for (const Deck& d : loadDecks(o->decks)) {
      const auto figures =
          std::count_if(d.slides.begin(), d.slides.end(), [](const Slide& s) { return s.preset.has_value(); });
      std::printf("ok %s: %zu slides, %td presets\n", d.path.c_str(), d.slides.size(), figures);
    }
  };
}

}  // namespace ll::cli
