// Presenter mode (`lightlab gui --slides DECK.md`): the deck, the slide on
// screen, and going from slide to slide. Arriving at a slide applies its
// preset (scene, camera, panes, compare mode) through applyPreset, keeping
// the presenter's UI scale. No GL or ImGui here, so it runs in headless tests;
// slide_panel.h draws it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "slides/deck.h"
#include "slides/slide_text.h"

struct ImFont;

namespace ll::gui {

struct AppState;

// UI scale presenter mode starts with (projectors), unless --ui-scale says otherwise.
inline constexpr float kPresenterUiScale = 1.6f;

struct PresenterState {
  std::optional<Deck> deck;  // empty: not presenting
  std::vector<std::vector<TextBlock>> text;  // each slide's Markdown as styled blocks
  std::vector<std::vector<TextBlock>> notes;
  int index = 0;                     // slide on screen, 0-based
  int applied = -1;                  // slide whose preset was applied last (-1 = none yet)
  std::optional<int> requested;      // set by the key callback, taken in the next frame
  bool showControls = false;         // Tab: the usual side panel instead of the slide
  bool showNotes = false;            // N: the speaker notes under the slide
  // Fonts of the slide text (owned by ImGui's atlas; null until built).
  ImFont* heading = nullptr;
  ImFont* title = nullptr;
  ImFont* bold = nullptr;
  ImFont* code = nullptr;

  bool active() const { return deck.has_value(); }
  int count() const { return deck ? static_cast<int>(deck->slides.size()) : 0; }
};

// Starts presenting `deck` at slide `start` (0-based, clamped).
void openDeck(AppState& app, Deck deck, int start = 0);
// Shows slide `index` (clamped) and applies its preset, if it has one. A
// slide without one keeps the view of the slide before it (the first slides,
// before any preset, show the deck's first). A preset without a camera shows
// the scene's own camera, as its figure does.
void goToSlide(AppState& app, int index);
// Asks for the slide `step` slides on from the one on screen or already asked for.
void requestStep(AppState& app, int step);
// Goes to the requested slide, if any. Call once per frame.
void takeSlideRequest(AppState& app);

}  // namespace ll::gui
