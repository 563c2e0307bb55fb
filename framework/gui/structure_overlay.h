// Drawing an accelerator's nodes over a pane: each box's 12 edges (or each
// sphere's outline) projected with the pane's camera into the rectangle where
// the pane's image is shown. Edges with an end behind the camera are skipped.
#pragma once

#include <vector>

#include "accel/accelerator.h"
#include "scene/camera.h"

struct ImDrawList;

namespace ll::gui {

// Projects a world point to image pixels of `camera` (its width x height,
// top-left origin). Returns false if the point is not in front of the eye.
bool projectToImage(const Camera& camera, const Vec3& p, float& px, float& py);
// The same, to screen coordinates in the rectangle (x, y, w, h) that shows the image.
bool projectToRect(const Camera& camera, const Vec3& p, float x, float y, float w, float h, float& sx, float& sy);

// Draws `nodes` into the screen rectangle (x, y, w, h) that shows `camera`'s
// image. At most `maxNodes` are drawn (the rest are counted in the return).
int drawStructure(ImDrawList* dl, const Camera& camera, const std::vector<NodeShape>& nodes,
                  float x, float y, float w, float h, int maxNodes = 4000);

}  // namespace ll::gui
