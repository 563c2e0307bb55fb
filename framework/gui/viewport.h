// The image area right of the side panel: the panes' images laid out 1, 2 or
// 4 at a time, or one compare view (wipe or difference heatmap), with a
// caption and banners over each image; and the camera controls, which act
// only when ImGui does not want the mouse or keyboard.
#pragma once

#include <string>
#include <vector>

#include "gui/app_state.h"

struct GLFWwindow;

namespace ll::gui {

// Uploads changed images, then draws into ImGui's background draw list over
// the rectangle (x, y, w, h) in window coordinates. Call between NewFrame and Render.
void drawViewport(AppState& app, float x, float y, float w, float h);

// Mouse: left drag orbits, right or middle drag pans, wheel zooms; in wipe
// mode dragging near the split line moves it. Keys: WASD/QE fly (Shift x4).
void handleCameraInput(AppState& app, GLFWwindow* window, float x, float y, float w, float h);

// Whether the pane's texture shows an image of its current technique (or
// cost view): false from a switch until the new technique's first image.
bool imageOnScreen(const PaneState& p);

// Caption `lines` wrapped to `width` pixels in the current ImGui font,
// between their fields (caption_wrap.h). Draw them with ImGui's wrap at
// the same width too: it then only cuts a single word wider than a line.
std::vector<std::string> wrapCaption(const std::vector<std::string>& lines, float width);

// One-letter pane names used everywhere in the GUI: A, B, C, D.
inline char paneLetter(int pane) {
  return static_cast<char>('A' + pane);
}

}  // namespace ll::gui
