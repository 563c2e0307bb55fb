// Presenter mode's left panel: the slide's text (headings, bullets, inline
// code, equations as Unicode text) in large type, its number, big previous /
// next buttons, and the speaker notes on demand. Keys (what presentation
// clickers send): Right, Down, PageDown, Space = next; Left, Up, PageUp,
// Backspace = previous; Home / End = first / last; Tab = the usual controls
// instead of the slide; N = speaker notes.
#pragma once

#include "gui/app_state.h"

namespace ll::gui {

// Adds the slide fonts (bold headings, bold, monospace, with Greek and math
// glyphs) to ImGui's font atlas at `pixels` body size; call while the atlas
// is being rebuilt, after the body font. Sets app.presenter's font pointers.
void addSlideFonts(AppState& app, float pixels);
// The glyph ranges of the body font in presenter mode (Latin, Greek, math).
const unsigned short* slideGlyphRanges();

// Handles a key press (GLFW key code) in presenter mode; true if it was one of ours.
bool handleSlideKey(AppState& app, int key);

// Draws the panel over (x, y, w, h) in window coordinates.
void drawSlidePanel(AppState& app, float x, float y, float w, float h);

}  // namespace ll::gui
