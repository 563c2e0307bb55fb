#include "gui/ray_inspector.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "gui/app_actions.h"
#include "gui/app_state.h"
#include "gui/structure_overlay.h"
#include "modules/registry.h"

namespace ll::gui {

namespace {

ImU32 kindColour(RayKind kind, float alpha) {
  const auto a = static_cast<int>(std::clamp(alpha, 0.15f, 1.0f) * 255.0f);
  switch (kind) {
    case RayKind::Camera: return IM_COL32(255, 255, 255, a);
    case RayKind::Reflection: return IM_COL32(80, 220, 255, a);
    case RayKind::Refraction: return IM_COL32(120, 255, 120, a);
    case RayKind::Shadow: return IM_COL32(255, 220, 60, a);
    case RayKind::Indirect: return IM_COL32(255, 140, 220, a);
  }
  return IM_COL32(255, 255, 255, a);
}

// Where the node's segment ends: its hit, the light (shadow rays), or far along the ray.
Vec3 segmentEnd(const RayTreeNode& n, float far) {
  if (n.hit || (n.kind == RayKind::Shadow && n.t > 0.0f)) return n.origin + n.direction * n.t;
  return n.origin + n.direction * far;
}

}  // namespace

void inspectPixel(AppState& app, int pane, Vec2 pixel) {
  app.inspector.pane = pane;
  app.inspector.pixel = pixel;
  app.inspector.request = ~uint64_t{0};  // force a recompute
}

void refreshRayTree(AppState& app) {
  RayInspector& in = app.inspector;
  if (in.pane < 0 || in.pane >= app.paneCount || !app.scene) {
    in.tree.reset();
    return;
  }
  PaneState& p = app.panes[static_cast<size_t>(in.pane)];
  const auto accel = p.renderer->accelerator();
  if (in.request == p.shown.request && accel == in.accel) return;
  in.request = p.shown.request;
  in.accel = accel;
  in.tree.reset();
  in.highlighted = -1;
  if (!accel) {
    in.note = "waiting for the accelerator";
    return;
  }
  try {
    const TechniqueInfo& info = findTechnique(p.technique);
    const RenderSettings settings = renderSettings(app, p);
    const RenderContext ctx{*app.scene, *accel, p.techniqueParams, settings, nullptr};
    const auto technique = info.make();
    if (!info.gpu) {
      technique->prepare(ctx);
      in.tree = technique->rayTree(ctx, in.pixel);
    }
    in.note = in.tree ? "" : p.technique + " draws no ray tree: choose raycast (its camera and shadow rays) or whitted";
  } catch (const std::exception& e) {
    in.note = e.what();
  }
}

void drawRayTree(ImDrawList* dl, const Camera& camera, const RayTree& tree, int highlighted, float x, float y,
                 float w, float h) {
  const auto toScreen = [&](const Vec3& p, ImVec2& out) { return projectToRect(camera, p, x, y, w, h, out.x, out.y); };
  // Misses are drawn this far: the camera's distance to its target, a scale of the view.
  const float far = 2.0f * glm::length(camera.target - camera.eye);
  dl->PushClipRect(ImVec2(x, y), ImVec2(x + w, y + h), true);
  for (size_t i = 0; i < tree.nodes.size(); ++i) {
    const RayTreeNode& n = tree.nodes[i];
    if (!n.intersected && n.kind != RayKind::Shadow) continue;
    ImVec2 a, b;
    if (!toScreen(n.origin, a)) continue;
    Vec3 end = segmentEnd(n, far);
    if (!toScreen(end, b)) {  // ends behind the camera: shorten until it does not
      for (int k = 0; k < 20 && !toScreen(end, b); ++k) end = n.origin + 0.5f * (end - n.origin);
      if (!toScreen(end, b)) continue;
    }
    const bool hot = static_cast<int>(i) == highlighted;
    const bool blocked = n.kind == RayKind::Shadow && isBlack(n.shadowTransmittance);
    const float weight = n.kind == RayKind::Shadow ? 0.6f : 0.35f + 0.65f * std::sqrt(maxComponent(n.throughput));
    const ImU32 colour = blocked ? IM_COL32(255, 70, 70, 200) : kindColour(n.kind, weight);
    dl->AddLine(a, b, hot ? IM_COL32(255, 0, 255, 255) : colour, hot ? 4.0f : 2.0f);
    if (n.hit) dl->AddCircleFilled(b, hot ? 5.0f : 3.0f, colour);
  }
  dl->PopClipRect();
}

void rayTreeSection(AppState& app) {
  if (!ImGui::CollapsingHeader("Ray tree", ImGuiTreeNodeFlags_DefaultOpen)) return;
  RayInspector& in = app.inspector;
  if (in.pane < 0) {
    ImGui::TextWrapped("Click a pixel of a raycast or whitted pane (without dragging) to see its rays.");
    return;
  }
  ImGui::Text("pane %c, pixel (%d, %d)", static_cast<char>('A' + in.pane), static_cast<int>(in.pixel.x),
              static_cast<int>(in.pixel.y));
  ImGui::SameLine();
  if (ImGui::SmallButton("clear")) {
    in.pane = -1;
    in.tree.reset();
    return;
  }
  if (!in.tree) {
    ImGui::TextWrapped("%s", in.note.c_str());
    return;
  }
  const RayTree& t = *in.tree;
  ImGui::Text("pixel radiance %.3g %.3g %.3g, %zu rays", static_cast<double>(t.pixel.r),
              static_cast<double>(t.pixel.g), static_cast<double>(t.pixel.b), t.nodes.size());
  ImGui::TextColored(ImVec4(1, 1, 1, 1), "camera");
  ImGui::SameLine();
  ImGui::TextColored(ImVec4(0.31f, 0.86f, 1, 1), "reflection");
  ImGui::SameLine();
  ImGui::TextColored(ImVec4(0.47f, 1, 0.47f, 1), "refraction");
  ImGui::SameLine();
  ImGui::TextColored(ImVec4(1, 0.86f, 0.24f, 1), "shadow");
  ImGui::SameLine();
  ImGui::TextColored(ImVec4(1, 0.27f, 0.27f, 1), "blocked");
  in.highlighted = -1;
  if (!ImGui::BeginTable("raytree", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit,
                         ImVec2(0.0f, 16.0f * ImGui::GetTextLineHeightWithSpacing())))
    return;
  ImGui::TableSetupColumn("ray");
  ImGui::TableSetupColumn("hit");
  ImGui::TableSetupColumn("weight");
  ImGui::TableSetupColumn("adds");
  ImGui::TableHeadersRow();
  std::vector<int> indent(t.nodes.size(), 0);
  for (size_t i = 0; i < t.nodes.size(); ++i) {
    const RayTreeNode& n = t.nodes[i];
    indent[i] = n.parent < 0 ? 0 : indent[static_cast<size_t>(n.parent)] + 1;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    char label[64];
    std::snprintf(label, sizeof label, "%*s%s##%zu", 2 * indent[i], "",
                  std::string(kRayKindNames[static_cast<size_t>(n.kind)]).c_str(), i);
    ImGui::Selectable(label, false, ImGuiSelectableFlags_SpanAllColumns);
    if (ImGui::IsItemHovered()) in.highlighted = static_cast<int>(i);
    ImGui::TableNextColumn();
    char what[160];
    if (n.kind == RayKind::Shadow)
      std::snprintf(what, sizeof what, "light %s", isBlack(n.shadowTransmittance) ? "blocked" : "visible");
    else if (!n.intersected)
      std::snprintf(what, sizeof what, "not traced (limit)");
    else if (!n.hit)
      std::snprintf(what, sizeof what, "background");
    else
      std::snprintf(what, sizeof what, "%s, t %.3g%s%s", n.object.c_str(), static_cast<double>(n.t),
                    n.fresnel ? (", F " + std::to_string(*n.fresnel).substr(0, 5)).c_str() : "",
                    n.totalInternalReflection ? ", TIR" : "");
    ImGui::TextUnformatted(what);
    if (ImGui::IsItemHovered() && n.hit)
      ImGui::SetTooltip("material %s\nn1 %.3g -> n2 %.3g (%s)\nlocal %.3g %.3g %.3g\nradiance %.3g %.3g %.3g",
                        n.material.c_str(), static_cast<double>(n.n1), static_cast<double>(n.n2),
                        n.entering ? "entering" : "leaving", static_cast<double>(n.local.r),
                        static_cast<double>(n.local.g), static_cast<double>(n.local.b),
                        static_cast<double>(n.radiance.r), static_cast<double>(n.radiance.g),
                        static_cast<double>(n.radiance.b));
    ImGui::TableNextColumn();
    ImGui::Text("%.3g", static_cast<double>(maxComponent(n.throughput)));
    ImGui::TableNextColumn();
    ImGui::Text("%.3g", static_cast<double>(maxComponent(n.contribution)));
  }
  ImGui::EndTable();
}

}  // namespace ll::gui
