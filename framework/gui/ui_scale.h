// Sizes in the GUI's drawing code, at the UI scale. applyUiScale (gui_app.cpp)
// builds the fonts and the ImGui style at the UI scale and leaves ImGui's
// FontGlobalScale at 1, so a fixed pixel size drawn by hand (a padding, a
// bar's height, a widget's width) must be scaled here, or it stays the size
// it has at scale 1 while the text around it doubles on a projector.
#pragma once

namespace ll::gui {

// The scale the fonts and style were last built at (UI scale times the
// monitor's content scale); 1 before the first build.
float uiScale();
void setUiScale(float scale);

// `px` pixels at UI scale 1, in pixels at the current UI scale.
inline float uiPx(float px) { return px * uiScale(); }

}  // namespace ll::gui
