// Saving what the window shows: the current GL framebuffer as an sRGB PNG
// (exactly the displayed bytes), plus a JSON sidecar describing where each
// pane was drawn, so tests and documentation can check the picture.
#pragma once

#include <string>

#include "gui/app_state.h"

namespace ll::gui {

// Reads the back buffer (width x height framebuffer pixels) and writes `path`
// (.png). Throws UserError if the file cannot be written.
void saveFramebufferPng(const std::string& path, int width, int height);
// The region (x, y, width, height) of the back buffer, framebuffer pixels from
// the top-left, of a framebuffer `framebufferHeight` pixels high.
void saveFramebufferRegionPng(const std::string& path, int framebufferHeight, int x, int y, int width, int height);

// Writes `path` with the .json extension: framebuffer size, and per pane its
// technique, accelerator, phase, passes, renders started (`starts`, grows on
// every restart), image version and the rectangle of its image in
// framebuffer pixels (top-left origin), scaled by `pixelScale` from window
// coordinates. Returns the sidecar's path.
std::string saveScreenshotSidecar(const AppState& app, const std::string& path, int width,
                                  int height, float pixelScale);

}  // namespace ll::gui
