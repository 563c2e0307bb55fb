// The ray-tree inspector: click a pixel of a pane whose technique traces
// recursively (whitted) and its ray tree is drawn over the image -- camera,
// reflected, refracted and shadow rays, each in its own colour -- and listed
// node by node in the side panel with its weight and contribution.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "render/ray_tree.h"
#include "scene/camera.h"

struct ImDrawList;

namespace ll {
class Accelerator;
class Scene;
}  // namespace ll

namespace ll::gui {

struct AppState;

struct RayInspector {
  int pane = -1;        // the inspected pane, -1 = none
  Vec2 pixel{0.0f};     // continuous image position (pixel centre = x + 0.5) at the render size
  std::optional<RayTree> tree;
  std::string note;     // why there is no tree (technique not recursive, no accelerator yet)
  // What the tree was computed from: recomputed when any of it changes.
  uint64_t request = 0;
  std::shared_ptr<const Accelerator> accel;
  int highlighted = -1;  // node under the mouse in the panel's list
};

// Selects the pixel at continuous image position `pixel` of pane `pane`.
void inspectPixel(AppState& app, int pane, Vec2 pixel);
// Recomputes the tree if the pane's render request, accelerator or the
// selection changed (cheap: one pixel). Call once per UI frame.
void refreshRayTree(AppState& app);
// Draws the tree over the rectangle (x, y, w, h) showing `camera`'s image.
void drawRayTree(ImDrawList* dl, const Camera& camera, const RayTree& tree, int highlighted, float x, float y,
                 float w, float h);
// The side-panel list of the tree's nodes.
void rayTreeSection(AppState& app);

}  // namespace ll::gui
