#include "gui/presenter.h"

#include <algorithm>

#include "gui/app_actions.h"

namespace ll::gui {

void openDeck(AppState& app, Deck deck, int start) {
  PresenterState& p = app.presenter;
  p.text.clear();
  p.notes.clear();
  for (const Slide& s : deck.slides) {
    p.text.push_back(slideText(s.markdown));
    p.notes.push_back(slideText(s.notes));
  }
  p.deck = std::move(deck);
  p.applied = -1;
  p.index = -1;
  goToSlide(app, start);
}

void goToSlide(AppState& app, int index) {
  PresenterState& p = app.presenter;
  if (!p.active()) return;
  index = std::clamp(index, 0, p.count() - 1);
  if (index == p.index) return;
  p.index = index;
  // The slide's preset. A slide without one keeps the view; arriving first at such a slide (the
  // deck opened there: --slide N) shows what stepping from the first slide would: the last preset
  // before it, else (a title slide before the deck's first preset) the first one after it.
  const auto hasPreset = [&](int i) { return p.deck->slides[static_cast<size_t>(i)].preset.has_value(); };
  int from = index;
  if (!hasPreset(from) && p.applied < 0) {
    while (from > 0 && !hasPreset(from)) --from;
    if (!hasPreset(from))
      for (from = index; from + 1 < p.count() && !hasPreset(from);) ++from;
  }
  const Slide& slide = p.deck->slides[static_cast<size_t>(from)];
  if (!slide.preset) return;
  const float uiScale = app.uiScale;  // the presenter's, not the preset's
  applyPreset(app, slide.preset->preset);
  app.uiScale = uiScale;
  if (!slide.preset->preset.camera && app.scene && app.loadingPath.empty()) resetCamera(app);
  p.applied = from;
}

void requestStep(AppState& app, int step) {
  PresenterState& p = app.presenter;
  if (!p.active()) return;
  p.requested = std::clamp(p.requested.value_or(p.index) + step, 0, p.count() - 1);
}

void takeSlideRequest(AppState& app) {
  PresenterState& p = app.presenter;
  if (!p.requested) return;
  const int index = *p.requested;
  p.requested.reset();
  goToSlide(app, index);
}

}  // namespace ll::gui
