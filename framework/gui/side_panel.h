// The control panel on the left of the window: scene, camera, layout and
// compare mode, one section per pane (technique, accelerator, parameters,
// statistics), presets, view settings and messages.
#pragma once

#include <string>

#include "gui/app_state.h"

struct GLFWwindow;

namespace ll::gui {

// Draws the panel at the window's left edge, `width` pixels wide and full height.
void drawSidePanel(AppState& app, GLFWwindow* window, float width, float height);

// Remembers where the last ImGui item was drawn, under `name` (window
// coordinates), for the screenshot sidecar and scripted UI tests.
void recordWidget(AppState& app, const std::string& name);
// Remembers the visible content area of the current window (the panel, or an
// open combo's list), under `name`.
void recordWindow(AppState& app, const std::string& name);

// Switches between windowed and fullscreen on the primary monitor.
void toggleFullscreen(AppState& app, GLFWwindow* window);

}  // namespace ll::gui
