#include "gui/structure_overlay.h"

#include <algorithm>
#include <cmath>

#include <imgui.h>

namespace ll::gui {

bool projectToImage(const Camera& camera, const Vec3& p, float& px, float& py) {
  const CameraFrame f(camera);
  const Vec3 d = p - camera.eye;
  const float z = glm::dot(d, f.w);
  if (!(z > 1e-6f * glm::length(d))) return false;
  const float sx = glm::dot(d, f.u) / (z * f.tanHalfFovY * camera.aspect());
  const float sy = glm::dot(d, f.v) / (z * f.tanHalfFovY);
  px = (sx + 1.0f) * 0.5f * static_cast<float>(camera.width);
  py = (1.0f - sy) * 0.5f * static_cast<float>(camera.height);
  return std::isfinite(px) && std::isfinite(py);
}

bool projectToRect(const Camera& camera, const Vec3& p, float x, float y, float w, float h, float& sx, float& sy) {
  float px = 0, py = 0;
  if (!projectToImage(camera, p, px, py)) return false;
  sx = x + px * w / static_cast<float>(camera.width);
  sy = y + py * h / static_cast<float>(camera.height);
  return true;
}

int drawStructure(ImDrawList* dl, const Camera& camera, const std::vector<NodeShape>& nodes,
                  float x, float y, float w, float h, int maxNodes) {
  const auto toScreen = [&](const Vec3& p, ImVec2& out) { return projectToRect(camera, p, x, y, w, h, out.x, out.y); };
  dl->PushClipRect(ImVec2(x, y), ImVec2(x + w, y + h), true);
  const ImU32 inner = IM_COL32(80, 220, 255, 170), leaf = IM_COL32(255, 200, 60, 170);
  const int count = std::min(static_cast<int>(nodes.size()), maxNodes);
  for (int i = 0; i < count; ++i) {
    const NodeShape& n = nodes[static_cast<size_t>(i)];
    const ImU32 colour = n.leaf ? leaf : inner;
    if (n.isSphere) {
      ImVec2 c, edge;
      const CameraFrame f(camera);
      if (toScreen(n.center, c) && toScreen(n.center + f.v * n.radius, edge))
        dl->AddCircle(c, std::hypot(edge.x - c.x, edge.y - c.y), colour, 32, 1.0f);
      continue;
    }
    if (!n.edges.empty()) {
      for (const auto& [from, to] : n.edges) {
        ImVec2 a, b;
        if (toScreen(from, a) && toScreen(to, b)) dl->AddLine(a, b, colour, 1.0f);
      }
      continue;
    }
    ImVec2 corner[8];
    bool ok[8];
    for (int k = 0; k < 8; ++k)
      ok[k] =
          toScreen(Vec3((k & 1) ? n.box.max.x : n.box.min.x, (k & 2) ? n.box.max.y : n.box.min.y,
                        (k & 4) ? n.box.max.z : n.box.min.z),
                   corner[k]);
    for (int a = 0; a < 8; ++a)
      for (int bit : {1, 2, 4}) {
        const int b = a | bit;
        if (b == a || !ok[a] || !ok[b]) continue;
        dl->AddLine(corner[a], corner[b], colour, 1.0f);
      }
  }
  dl->PopClipRect();
  return static_cast<int>(nodes.size()) - count;
}

}  // namespace ll::gui
