// The operations that change an AppState: open and reload scenes, apply and
// capture presets, pick techniques and accelerators, and keep the pane
// renderers fed. None of them blocks on a render or a scene load, and none
// throws on bad input: errors become messages and the previous state stays.
// No GL here, so all of it runs in headless tests.
#pragma once

#include <string>
#include <vector>

#include "gui/app_state.h"

namespace ll::gui {

// Gives every pane its default technique (the registry's i-th, so panes
// differ once several exist) and accelerator (the first registered after
// brute force, if any), with default parameters.
void initPanes(AppState& app);

void addMessage(AppState& app, const std::string& text, bool error = true);

// Pane views by their preset names: image, nodes, primitives.
const char* viewName(PaneView view);
PaneView viewFromName(const std::string& name);

// Starts loading a scene in the background; the current scene stays until it
// succeeds. keepCamera = false resets the view to the new scene's camera.
// A load still running is abandoned: its result is dropped, nothing waits for it.
void openScene(AppState& app, const std::string& path, bool keepCamera = false);
// Installs a finished load (or reports its error). Call once per frame.
void pollSceneLoad(AppState& app);
// Reloads the scene when its file changed on disk (checked at most twice a second).
void watchSceneFile(AppState& app);
// Blocks until a pending scene load is done (for --screenshot and tests).
void waitForSceneLoad(AppState& app);

// A dropped file: a view preset (JSON with "lightlab_preset") or a scene.
void openDroppedFile(AppState& app, const std::string& path);

// Applies a preset; throws nothing (errors become messages).
void applyPreset(AppState& app, const ViewPreset& preset);
bool loadPresetFile(AppState& app, const std::string& path);
ViewPreset capturePreset(const AppState& app);
bool savePresetFile(AppState& app, const std::string& path);

// Changes a pane's technique or accelerator. Each keeps its own parameter
// values per pane: switching back restores them; a first switch gets the
// defaults. Unknown names become messages.
void setTechnique(AppState& app, int pane, const std::string& name);
void setAccelerator(AppState& app, int pane, const std::string& name);

// Restores the scene's camera / frames the scene's bounds.
void resetCamera(AppState& app);
void frameScene(AppState& app);

// Render size of every pane: the app's, or the scene camera's.
RenderSettings renderSettings(const AppState& app, const PaneState& pane);

// Submits changed panes to their renderers (all of them after a camera or
// scene change) and stops hidden ones. Call once per frame.
void submitPanes(AppState& app);
// Copies each pane's snapshot and asks the background worker for what
// changed: display bytes, errors against the reference pane, the difference
// heatmap. Collects finished errors. Call once per frame.
void refreshPanes(AppState& app);
// A pane renders when it is shown or used by the compare mode or as the reference.
bool paneActive(const AppState& app, int pane);
bool allPanesFinished(const AppState& app);

// Quitting: cancels every pane's work and waits at most `seconds` for all of it
// (panes and scene loads) to stop. Returns false if something still runs; the
// caller then ends the process without joining it (closing must not hang).
bool stopAllWork(AppState& app, double seconds);

// Whether `path` is a view preset (a .json file tagged "lightlab_preset" near its top).
bool isPresetFile(const std::string& path);

// Scene files under `folders` (.json scenes, not presets, and .obj), sorted.
std::vector<std::string> findSceneFiles(const std::vector<std::string>& folders);

}  // namespace ll::gui
