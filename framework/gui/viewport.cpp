#include "gui/viewport.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <string>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "core/error.h"
#include "core/image.h"
#include "gui/accuracy_plot.h"
#include "gui/app_actions.h"
#include "gui/caption_wrap.h"
#include "gui/legend_labels.h"
#include "gui/pane_labels.h"
#include "gui/ray_inspector.h"
#include "gui/structure_overlay.h"
#include "gui/ui_scale.h"
#include "gui/view_camera.h"
#include "modules/registry.h"

namespace ll::gui {

namespace {

struct Rect {
  float x, y, w, h;
  bool contains(ImVec2 p) const { return p.x >= x && p.y >= y && p.x < x + w && p.y < y + h; }
};

// Cells of the pane grid: 1 = whole area; 2 = side by side (stacked if the area is tall); 4 = 2
// x 2.
Rect cellOf(int index, int count, Rect area) {
  if (count <= 1) return area;
  if (count == 2) {
    if (area.w >= area.h) return {area.x + index * area.w / 2, area.y, area.w / 2, area.h};
    return {area.x, area.y + index * area.h / 2, area.w, area.h / 2};
  }
  return {area.x + (index % 2) * area.w / 2, area.y + (index / 2) * area.h / 2, area.w / 2,
          area.h / 2};
}

// The largest rectangle of the image's aspect ratio centred in `cell`, with a margin.
Rect fitImage(Rect cell, int imageW, int imageH, float margin) {
  const float w = std::max(cell.w - 2 * margin, 1.0f), h = std::max(cell.h - 2 * margin, 1.0f);
  const float aspect = static_cast<float>(imageW) / static_cast<float>(std::max(imageH, 1));
  float fw = w, fh = w / aspect;
  if (fh > h) {
    fh = h;
    fw = h * aspect;
  }
  return {std::floor(cell.x + (cell.w - fw) / 2), std::floor(cell.y + (cell.h - fh) / 2),
          std::floor(fw), std::floor(fh)};
}

// Where a pane's picture and its caption go in the pane's cell.
struct PaneLayout {
  Rect picture;
  float captionX = 0.0f, captionY = 0.0f, captionWidth = 0.0f;  // width 0: the caption goes over the picture
};

float captionHeight(const std::vector<std::string>& lines, float width);  // below

// The caption where it hides no picture: beside it when the cell has the width to spare, or would
// after the picture shrinks to 75 % of its width (a tall cell: panes stacked in a narrow viewport;
// a smaller picture reads better than one whose middle is under five lines of text); else above it
// when the cell has the height (a wide picture in a tall cell), the two centred together; else
// over the picture's top. smallTiles (the light-path view's mosaic): above even if the picture
// shrinks more. aboveAtLeast: the height kept above the picture at least (the tallest caption of
// the panes, so that pictures side by side stay level). No caption lines: the whole cell is the
// picture's.
PaneLayout layoutPane(Rect cell, int imageW, int imageH, const std::vector<std::string>& caption, bool smallTiles,
                      float aboveAtLeast) {
  const float margin = 6.0f;
  PaneLayout out;
  out.picture = fitImage(cell, imageW, imageH, margin);
  if (caption.empty()) return out;
  const Rect whole = out.picture;
  const float besideMin = uiPx(190.0f);
  if (cell.w - 3.0f * margin - besideMin >= 0.75f * whole.w) {
    const float width = std::clamp(cell.w - whole.w - 3.0f * margin, besideMin, uiPx(320.0f));
    Rect& r = out.picture;
    r = fitImage({cell.x, cell.y, cell.w - width - margin, cell.h}, imageW, imageH, margin);
    r.x = std::floor(cell.x + (cell.w - (r.w + margin + width)) / 2.0f);
    out.captionX = r.x + r.w + margin;
    out.captionY = r.y;
    out.captionWidth = width;
    return out;
  }
  const float width = cell.w - 2.0f * margin, own = captionHeight(caption, width);
  const float height = std::max(own, aboveAtLeast);
  if (smallTiles || cell.h - 2.0f * margin - height >= 0.85f * whole.h) {
    Rect& r = out.picture;
    r = fitImage({cell.x, cell.y + height, cell.w, std::max(cell.h - height, 1.0f)}, imageW, imageH, margin);
    r.y = std::max(std::floor(cell.y + (cell.h - (height + r.h)) / 2.0f + height), cell.y + height);
    out.captionX = cell.x + margin;
    out.captionY = r.y - own;
    out.captionWidth = width;
  }
  return out;
}

ImU32 srgbColor(Rgb linear) {
  const auto c = [](float v) {
    return static_cast<int>(std::lround(linearToSrgb(std::clamp(v, 0.0f, 1.0f)) * 255));
  };
  return IM_COL32(c(linear.r), c(linear.g), c(linear.b), 255);
}

enum class Anchor { Top, Bottom };  // whether y is the box's top or bottom edge

// Text lines, wrapped to maxWidth, in a filled box at (x, y); the box is
// recorded in `overlays` (for the screenshot sidecar). Returns its height.
float captionBox(std::vector<std::array<float, 4>>& overlays, ImDrawList* dl, float x, float y,
                 const std::vector<std::string>& lines, ImU32 bg, float maxWidth,
                 Anchor anchor = Anchor::Top) {
  const float pad = uiPx(4.0f);
  const float wrap = std::max(maxWidth - 2 * pad, 1.0f);
  const std::vector<std::string> wrapped = wrapCaption(lines, wrap);
  float width = 0.0f, height = 2 * pad;
  for (const std::string& l : wrapped) {
    const ImVec2 size = ImGui::CalcTextSize(l.c_str(), nullptr, false, wrap);
    width = std::max(width, size.x);
    height += size.y;
  }
  width = std::min(width + 2 * pad, maxWidth);
  if (anchor == Anchor::Bottom) y -= height;
  dl->AddRectFilled(ImVec2(x, y), ImVec2(x + width, y + height), bg, 3.0f);
  overlays.push_back({x, y, width, height});
  float ty = y + pad;
  for (const std::string& l : wrapped) {
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(x + pad, ty), IM_COL32_WHITE,
                l.c_str(), nullptr, wrap);
    ty += ImGui::CalcTextSize(l.c_str(), nullptr, false, wrap).y;
  }
  return height;
}

std::string formatRate(double raysPerSecond) {
  char buf[64];
  if (raysPerSecond >= 1e6)
    std::snprintf(buf, sizeof buf, "%.2f Mrays/s", raysPerSecond / 1e6);
  else
    std::snprintf(buf, sizeof buf, "%.0f krays/s", raysPerSecond / 1e3);
  return buf;
}

// Whether task `id` belongs to the assignment in focus (all, with no focus).
bool inFocus(const AppState& app, const std::string& id) {
  return app.assignment.empty() || id.rfind(app.assignment + ".", 0) == 0;
}

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// ", about 12 s left" for a phase `fraction` done after `seconds`, once the estimate means something.
std::string timeLeft(double fraction, double seconds) {
  if (fraction < 0.02 || fraction >= 1.0 || seconds < 1.0) return "";
  char buf[64];
  const double left = seconds * (1.0 - fraction) / fraction;
  if (left < 90.0)
    std::snprintf(buf, sizeof buf, ", about %.0f s left", std::max(left, 1.0));
  else
    std::snprintf(buf, sizeof buf, ", about %.0f min left", left / 60.0);
  return buf;
}

// What the pane's worker does now, with its progress and the time so far:
// "form factors (hemicube, 812 patches)  37 %  12.0 s, about 20 s left", "pass 3/16  47 %  1.20 s".
std::string phaseLine(const PaneSnapshot& s) {
  char buf[256];
  const double f = s.phaseFraction;
  char pct[16] = "";
  if (f >= 0.0) std::snprintf(pct, sizeof pct, "  %.0f %%", 100.0 * f);
  const std::string left = timeLeft(f, secondsSince(s.phaseStarted));
  const bool working = s.phase == PaneSnapshot::Phase::Building || s.phase == PaneSnapshot::Phase::Rendering;
  if (working && !s.phaseName.empty() && s.phaseName != "pass") {
    const std::string name = s.phaseName == "preview" ? "low-resolution preview" : s.phaseName;
    std::snprintf(buf, sizeof buf, "%s%s  %.1f s%s", name.c_str(), pct, s.elapsed(), left.c_str());
    return buf;
  }
  if (s.phase == PaneSnapshot::Phase::Building) {
    std::snprintf(buf, sizeof buf, "building the accelerator  %.1f s", s.elapsed());
    return buf;
  }
  const double rays = static_cast<double>(s.stats.work.totalRays());
  const std::string rate =
      s.passes > 0 && s.passSeconds > 0 && rays > 0 ? "  " + formatRate(rays / s.passSeconds) : "";
  const bool rendering = s.phase == PaneSnapshot::Phase::Rendering;
  std::snprintf(buf, sizeof buf, "pass %d/%d%s  %.2f s%s%s%s", std::min(s.passes + (rendering ? 1 : 0), std::max(s.totalPasses, 1)),
                s.totalPasses, rendering ? pct : "", s.elapsed(), rate.c_str(), rendering ? left.c_str() : "",
                s.phase == PaneSnapshot::Phase::Done ? "  done" : "");
  return buf;
}


std::vector<std::string> paneCaption(const AppState& app, int index, const std::string& differs) {
  const PaneState& p = app.panes[static_cast<size_t>(index)];
  const PaneSnapshot& s = p.shown;
  std::vector<std::string> lines;
  if (isCostView(s.view)) {
    lines.push_back(std::string(1, paneLetter(index)) + "  " + p.accelerator + ": " +
                    (s.view == PaneView::NodesVisited ? "nodes visited" : "primitives tested") +
                    " per camera ray");
  } else {
    lines.push_back(std::string(1, paneLetter(index)) + "  " + p.technique + "  /  " + p.accelerator +
                    (s.view == PaneView::LightPaths ? "  |  split by light path" : "") +
                    (differs.empty() ? "" : "  |  " + differs));
  }
  // The student tree: whose code this picture ran, for the tasks in focus. Where a stub ran, the
  // reference answered for it.
  std::vector<std::string> yours, reference;
  for (const auto& [id, byReference] : s.tasksRan)
    if (inFocus(app, id)) (byReference || s.missingTasks.count(id) ? reference : yours).push_back(id);
  if (!yours.empty() || !reference.empty())
    lines.push_back((yours.empty() ? std::string() : "your " + joinNames(yours, " ")) +
                    (yours.empty() || reference.empty() ? "" : "  |  ") +
                    (reference.empty() ? std::string() : "reference " + joinNames(reference, " ")));
  char buf[160];
  switch (s.phase) {
    case PaneSnapshot::Phase::Building:
    case PaneSnapshot::Phase::Rendering:
    case PaneSnapshot::Phase::Done: {
      lines.push_back(phaseLine(s));
      // Where the time went, once more than the passes took it; only the parts that took time (a
      // narrow pane wraps this line, and every line takes room from the picture).
      if (s.phase == PaneSnapshot::Phase::Done && s.seconds - s.passSeconds > 0.05) {
        std::string line = "time:";
        for (const auto& [name, seconds] : {std::pair{"build", s.requestBuildSeconds}, {"preview", s.previewSeconds},
                                            {"prepare", s.prepareSeconds}})
          if (seconds >= 0.005) {
            std::snprintf(buf, sizeof buf, "%s %s %.2f", line == "time:" ? "" : "  +", name, seconds);
            line += buf;
          }
        std::snprintf(buf, sizeof buf, "%s passes %.2f s", line == "time:" ? "" : "  +", s.passSeconds);
        lines.push_back(line + buf);
      }
      break;
    }
    case PaneSnapshot::Phase::Failed:
      lines.emplace_back("failed (see below)");
      break;
    case PaneSnapshot::Phase::Stopped:
      lines.emplace_back("stopped");
      break;
    case PaneSnapshot::Phase::Idle:
      lines.emplace_back("waiting for the scene...");
      break;
  }
  if (p.hasError) {
    std::snprintf(buf, sizeof buf, "vs %c: relMSE %.3g  RMSE %.4g  SSIM %.4f", paneLetter(app.compare.reference),
                  p.error.relmse, p.error.rmse, p.error.ssim);
    lines.emplace_back(buf);
  }
  if (s.view == PaneView::LightPaths && s.lightPathTiles.empty() && s.image)
    lines.emplace_back("light paths: " + p.technique +
                       " does not split its picture by light path (path does; radiosity with a "
                       "form-factor matrix, by bounce)");
  if (s.stats.skipped) {  // --set effects=measured: what was left out, and what it cost in error
    const SkippedWork& w = *s.stats.skipped;
    std::snprintf(buf, sizeof buf, "left out (measured): %s; relMSE %.2g of %.2g", w.skipped.c_str(), w.errorAdded,
                  w.tolerance);
    lines.emplace_back(buf);
  }
  if (app.scene && !isCostView(s.view)) {
    const EffectSet missed = app.scene->effects.minus(findTechnique(p.technique).simulatesIn(*app.scene, p.techniqueParams));
    if (!missed.empty()) lines.push_back("misses: " + joinNames(missed.names()));
  }
  return lines;
}

// The student-task banner of a pane, shown under its picture (never over it):
// one line naming the stubs and broken rules of the assignment in focus, or,
// unfolded by a click, one line per task.
std::vector<std::string> bannerLines(const AppState& app, const PaneState& p) {
  std::vector<std::string> striped, same, broken, lines;
  for (const auto& [id, what] : p.shown.missingTasks)
    if (inFocus(app, id)) (p.shown.exactFallbacks.count(id) ? same : striped).push_back(id);
  for (const auto& [id, what] : p.shown.taskViolations)
    if (inFocus(app, id)) broken.push_back(id);
  if (striped.empty() && same.empty() && broken.empty()) return lines;
  if (!p.bannerOpen) {  // one line, cut to the width where drawn (oneLine)
    std::string line = "[+]";
    if (!striped.empty()) line += " Stubs " + joinNames(striped, " ") + " (striped)";
    if (!same.empty()) line += " Stubs " + joinNames(same, " ");
    if (!broken.empty()) line += " Rule broken: " + joinNames(broken, " ");
    lines.push_back(line + " -- click for details");
    return lines;
  }
  lines.emplace_back("[-] Still stubs here (click to fold):");
  for (const auto& [id, what] : p.shown.missingTasks)
    if (inFocus(app, id)) {
      // "camera rays (assignments/a2_raycasting/camera_ray.cpp)" -> "camera rays, camera_ray.cpp"
      std::string shown = what;
      const auto open = shown.find(" ("), slash = shown.rfind('/');
      if (open != std::string::npos && slash != std::string::npos && slash > open && shown.back() == ')')
        shown = shown.substr(0, open) + ", " + shown.substr(slash + 1, shown.size() - slash - 2);
      lines.push_back(id + " " + shown + (p.shown.exactFallbacks.count(id) ? ": reference shown" : ": reference shown, striped"));
    }
  for (const auto& [id, what] : p.shown.taskViolations)
    if (inFocus(app, id)) lines.push_back(id + ": " + what);
  return lines;
}

// `text` cut to fit `width` pixels on one line (with "..." when cut).
std::string oneLine(const std::string& text, float width) {
  if (ImGui::CalcTextSize(text.c_str()).x <= width) return text;
  std::string cut = text;
  while (!cut.empty() && ImGui::CalcTextSize((cut + "...").c_str()).x > width) cut.pop_back();
  return cut + "...";
}

// The banner's lines as drawn `width` wide: folded, one line however narrow.
std::vector<std::string> bannerLinesAt(const AppState& app, const PaneState& p, float width) {
  std::vector<std::string> lines = bannerLines(app, p);
  if (!p.bannerOpen && lines.size() == 1) lines[0] = oneLine(lines[0], width - uiPx(8.0f) - 2.0f);
  return lines;
}

// Height of a captionBox of `lines` wrapped to `width` (0 for no lines).
float captionHeight(const std::vector<std::string>& lines, float width) {
  if (lines.empty()) return 0.0f;
  const float pad = uiPx(4.0f);
  const float wrap = std::max(width - 2 * pad, 1.0f);
  float height = 2 * pad;
  for (const std::string& l : wrapCaption(lines, wrap)) height += ImGui::CalcTextSize(l.c_str(), nullptr, false, wrap).y;
  return height + 2.0f;
}

// The banner under the image rectangle r, `width` wide from x (the space was
// kept free: bannerSpace), and a failed render's error over the image. An
// unfolded banner taller than that space rises over the picture's bottom
// rather than run past `bottom` (the cell's), where it would be cut.
void paneBanners(ImDrawList* dl, AppState& app, int index, Rect r, float x, float width, float bottom) {
  const PaneState& p = app.panes[static_cast<size_t>(index)];
  const auto lines = bannerLinesAt(app, p, width);
  if (!lines.empty()) {
    const float top = std::max(std::min(r.y + r.h + 2.0f, bottom - captionHeight(lines, width)), r.y);
    const float h = captionBox(app.overlayRects, dl, x, top, lines, IM_COL32(150, 20, 120, 230), width);
    app.widgetRects[std::string("pane.") + paneLetter(index) + ".banner"] = {x, top, width, h};
  }
  if (p.shown.phase == PaneSnapshot::Phase::Failed) {
    const float h = ImGui::GetTextLineHeight() + 8.0f;
    captionBox(app.overlayRects, dl, r.x, r.y + r.h / 2 - h / 2, {"Error: " + p.shown.error},
               IM_COL32(170, 30, 30, 240), r.w);
  }
}

// The height to keep free under a pane's picture, `width` wide, for its banner: all of it, up to
// `most` (an unfolded banner's list of stubs would leave a thumbnail of the picture).
float bannerSpace(const AppState& app, const PaneState& p, float width, float most = kInfinity) {
  return std::min(captionHeight(bannerLinesAt(app, p, width), width), most);
}

// Uploads bytes the background worker finished since the last frame.
void uploadFinished(AppState& app) {
  for (PaneState& p : app.panes)
    if (auto d = p.display->take()) p.texture.upload(*d);
  if (auto r = app.diff.mail->take()) {
    app.diff.texture.upload(r->image);
    app.diff.usedMax = r->usedMax;
    app.diff.valid = true;
  }
}

// A colour bar from 0 to maxValue over the labels 0, max/2 and max (those that fit: legend_labels.h).
void drawLegend(ImDrawList* dl, Rect r, float maxValue, bool automatic) {
  const float barH = uiPx(14.0f);
  const int segments = 64;
  for (int i = 0; i < segments; ++i) {
    const float t0 = static_cast<float>(i) / segments, t1 = static_cast<float>(i + 1) / segments;
    const ImU32 c0 = srgbColor(errorColormap(t0)), c1 = srgbColor(errorColormap(t1));
    dl->AddRectFilledMultiColor(ImVec2(r.x + r.w * t0, r.y), ImVec2(r.x + r.w * t1, r.y + barH), c0,
                                c1, c1, c0);
  }
  const float ty = r.y + barH + 2.0f;
  const auto measure = [](std::string_view s) { return ImGui::CalcTextSize(s.data(), s.data() + s.size()).x; };
  for (const LegendLabel& l : legendLabels(r.w, maxValue, automatic, uiPx(8.0f), measure))
    dl->AddText(ImVec2(r.x + l.x, ty), IM_COL32_WHITE, l.text.c_str());
}

// The light-path view's labels: each tile's class and share, at the tile's bottom-left corner (the caption
// covers the top of the first tile).
void drawLightPathLabels(AppState& app, ImDrawList* dl, const PaneState& p, Rect r) {
  if (p.shown.view != PaneView::LightPaths || !p.shown.image) return;
  const float sx = r.w / static_cast<float>(p.shown.image->width()), sy = r.h / static_cast<float>(p.shown.image->height());
  for (const MosaicTile& t : p.shown.lightPathTiles) {
    const float x = r.x + static_cast<float>(t.x) * sx, w = static_cast<float>(t.w) * sx;
    const float bottom = r.y + static_cast<float>(t.y + t.h) * sy;
    std::vector<std::string> lines{t.name};
    if (t.share >= 0.0) lines.push_back(t.shareText());
    // The error without the class only where it fits on one line (small tiles at a projector's UI scale).
    if (t.relMseWithout >= 0.0 &&
        ImGui::CalcTextSize(t.relMseText().c_str()).x + 4.0f + uiPx(8.0f) <= w)
      lines.push_back(t.relMseText());
    captionBox(app.overlayRects, dl, x + 2.0f, bottom - 2.0f, lines, IM_COL32(0, 0, 0, 190), w - 4.0f, Anchor::Bottom);
  }
}

// The structure overlay of pane `i` over its image rectangle r, above its bottom `bottomMargin` pixels.
void drawPaneStructure(ImDrawList* dl, AppState& app, int i, Rect r, float bottomMargin) {
  PaneState& p = app.panes[static_cast<size_t>(i)];
  const auto accel = p.renderer->accelerator();
  if (!accel) return;
  if (accel != p.overlayAccel || app.structureDepth != p.overlayDepth) {
    p.overlayAccel = accel;
    p.overlayDepth = app.structureDepth;
    p.overlayNodes = accel->nodesAtDepth(app.structureDepth);
  }
  const Camera camera = renderCamera(*app.scene, renderSettings(app, p));
  // The lines stop above the heatmap legend (bottomMargin high), which must stay legible.
  dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h - bottomMargin), true);
  const int hidden = drawStructure(dl, camera, p.overlayNodes, r.x, r.y, r.w, r.h);
  dl->PopClipRect();
  char buf[96];
  if (p.overlayNodes.empty())
    std::snprintf(buf, sizeof buf, "%s has no nodes to draw", p.accelerator.c_str());
  else
    std::snprintf(buf, sizeof buf, "%zu nodes at depth %d%s", p.overlayNodes.size(),
                  app.structureDepth, hidden > 0 ? " (first 4000 drawn)" : "");
  captionBox(app.overlayRects, dl, r.x, r.y + r.h - bottomMargin, {buf}, IM_COL32(0, 0, 0, 170),
             r.w, Anchor::Bottom);
}

Rect compareArea(const AppState& app, Rect area) {
  const PaneState& a = app.panes[static_cast<size_t>(app.compare.paneA)];
  const int w = a.texture.valid() ? a.texture.width() : 1,
            h = a.texture.valid() ? a.texture.height() : 1;
  const float legend =
      app.compare.mode == CompareMode::Difference ? uiPx(40.0f) : 0.0f;
  const PaneState& b = app.panes[static_cast<size_t>(app.compare.paneB)];
  const float banners = app.compare.mode == CompareMode::Wipe
                            ? std::max(bannerSpace(app, a, area.w / 2, 0.3f * area.h),
                                       bannerSpace(app, b, area.w / 2, 0.3f * area.h))
                            : 0.0f;
  return fitImage({area.x, area.y, area.w, area.h - legend - banners}, w, h, 8.0f);
}

// The newest error of the last few seconds, over the top of the image area,
// so a bad scene or preset is noticed even with the panel scrolled away.
void errorToast(ImDrawList* dl, AppState& app, Rect area) {
  constexpr auto kShowFor = std::chrono::seconds(10);
  for (auto it = app.messages.rbegin(); it != app.messages.rend(); ++it) {
    if (std::chrono::steady_clock::now() - it->when > kShowFor) return;
    if (!it->error) continue;
    captionBox(app.overlayRects, dl, area.x + 8.0f, area.y + area.h - 8.0f, {it->text},
               IM_COL32(170, 30, 30, 240), area.w - 16.0f, Anchor::Bottom);
    return;
  }
}


// The font and size of projector labels: the large font when built, else the UI font scaled up.
ImFont* labelFont(const AppState& app, float* size) {
  if (app.largeFont) {
    *size = app.largeFont->FontSize;
    return app.largeFont;
  }
  *size = ImGui::GetFontSize() * 1.25f;
  return ImGui::GetFont();
}

// The projector label of pane i: one line in large type at the top-left of
// its image, cut to the image's width; returns the box's height.
float projectorLabel(AppState& app, ImDrawList* dl, int i, const std::string& text, Rect r) {
  float size = 0.0f;
  ImFont* font = labelFont(app, &size);
  const float pad = 0.15f * size, accent = 0.15f * size;
  const auto width = [&](const std::string& t) { return font->CalcTextSizeA(size, FLT_MAX, 0.0f, t.c_str()).x; };
  std::string shown = text;
  const float room = r.w - 2 * pad - accent;
  if (width(shown) > room) {
    while (!shown.empty() && width(shown + "...") > room) shown.pop_back();
    shown += "...";
  }
  const float w = std::min(width(shown) + 2 * pad + accent, r.w), h = size + 2 * pad;
  const auto c = paneColor(i);
  dl->AddRectFilled(ImVec2(r.x, r.y), ImVec2(r.x + w, r.y + h), IM_COL32(0, 0, 0, 190), 3.0f);
  dl->AddRectFilled(ImVec2(r.x, r.y), ImVec2(r.x + accent, r.y + h), IM_COL32(c[0], c[1], c[2], 255));
  dl->AddText(font, size, ImVec2(r.x + accent + pad, r.y + pad), IM_COL32_WHITE, shown.c_str());
  app.overlayRects.push_back({r.x, r.y, w, h});
  app.labelRects.push_back({r.x, r.y, w, h});
  app.paneLabels.push_back(shown);
  return h;
}

// What a pane shows while it has no picture of its current technique yet: a
// neutral card with the technique, the phase and its progress (never the
// previous technique's image).
void drawPlaceholder(AppState& app, ImDrawList* dl, const PaneState& p, Rect r) {
  dl->AddRectFilled(ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h), IM_COL32(52, 52, 60, 255));
  float size = 0.0f;
  ImFont* font = labelFont(app, &size);
  const PaneSnapshot& s = p.shown;
  std::string status = s.request != p.submitted                 ? "starting"
                       : s.phase == PaneSnapshot::Phase::Idle     ? "waiting for the scene"
                       : s.phase == PaneSnapshot::Phase::Failed ? "failed"
                       : s.phase == PaneSnapshot::Phase::Stopped ? "stopped"
                                                                 : phaseLine(s);
  const float cy = r.y + r.h / 2;
  const auto centred = [&](const std::string& t, float y, ImFont* f, float sz) {
    const float tw = f->CalcTextSizeA(sz, FLT_MAX, r.w - 16.0f, t.c_str()).x;
    dl->AddText(f, sz, ImVec2(r.x + std::max((r.w - tw) / 2, 8.0f), y), IM_COL32(235, 235, 235, 255), t.c_str(),
                nullptr, r.w - 16.0f);
  };
  centred(p.technique, cy - size * 1.6f, font, size);
  centred(status, cy, ImGui::GetFont(), ImGui::GetFontSize());
  if (s.phaseFraction >= 0.0 && (s.phase == PaneSnapshot::Phase::Rendering || s.phase == PaneSnapshot::Phase::Building)) {
    const float bw = r.w * 0.6f, bh = 0.35f * size, bx = r.x + (r.w - bw) / 2, by = cy + ImGui::GetTextLineHeight() * 1.6f;
    dl->AddRectFilled(ImVec2(bx, by), ImVec2(bx + bw, by + bh), IM_COL32(30, 30, 34, 255), bh / 2);
    dl->AddRectFilled(ImVec2(bx, by), ImVec2(bx + bw * static_cast<float>(std::clamp(s.phaseFraction, 0.0, 1.0)), by + bh),
                      IM_COL32(90, 170, 250, 255), bh / 2);
  }
}

// Splits `area` between the panes and the cost-of-accuracy plot: beside them
// or under them, whichever leaves the panes' pictures larger.
Rect layoutPlot(AppState& app, Rect area, Rect* plot) {
  constexpr float kShare = 0.4f;  // of the width or height, for the plot
  const Rect besidePanes{area.x, area.y, area.w * (1 - kShare), area.h};
  const Rect underPanes{area.x, area.y, area.w, area.h * (1 - kShare)};
  const PaneState& first = app.panes[0];
  const int iw = first.texture.valid() ? first.texture.width() : 4, ih = first.texture.valid() ? first.texture.height() : 3;
  const auto imageArea = [&](Rect panes) {
    const Rect r = fitImage(cellOf(0, app.paneCount, panes), iw, ih, 6.0f);
    return r.w * r.h;
  };
  if (imageArea(besidePanes) >= imageArea(underPanes)) {
    *plot = {area.x + besidePanes.w, area.y, area.w - besidePanes.w, area.h};
    return besidePanes;
  }
  *plot = {area.x, area.y + underPanes.h, area.w, area.h - underPanes.h};
  return underPanes;
}

void drawViewportContent(AppState& app, float x, float y, float w, float h);  // below

}  // namespace

bool imageOnScreen(const PaneState& p) {
  // What the pane is set to show; until the worker takes a switch up, the old image is not it.
  const std::string shows = viewShows(p.view, p.technique, p.accelerator);
  return p.texture.valid() && p.shown.image && p.texture.version() > p.shown.clearedAt && p.shown.imageShows == shows;
}

void drawViewport(AppState& app, float x, float y, float w, float h) {
  drawViewportContent(app, x, y, w, h);
  errorToast(ImGui::GetBackgroundDrawList(), app, {x, y, w, h});
  // For a few seconds after hiding the panel: how to bring it back.
  if (app.panelHidden && secondsSince(app.panelHiddenAt) < 6.0)
    captionBox(app.overlayRects, ImGui::GetBackgroundDrawList(), x + 8.0f, y + h - 8.0f,
               {app.presenter.active() ? "H shows the slide again" : "H shows the panel again"},
               IM_COL32(0, 0, 0, 200), w - 16.0f, Anchor::Bottom);
}

namespace {
void drawViewportContent(AppState& app, float x, float y, float w, float h) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  Rect area{x, y, w, h};
  dl->AddRectFilled(ImVec2(x, y), ImVec2(x + w, y + h), IM_COL32(28, 28, 32, 255));
  for (auto& r : app.paneRects) r = {0, 0, 0, 0};
  app.overlayRects.clear();
  app.labelRects.clear();
  app.paneLabels.clear();
  app.compareRect = {0, 0, 0, 0};
  app.plotRect = {0, 0, 0, 0};
  uploadFinished(app);
  if (app.showPlot) {
    Rect plot{};
    area = layoutPlot(app, area, &plot);
    drawAccuracyPlot(dl, accuracyPlot(app), plot.x, plot.y, plot.w, plot.h);
    app.plotRect = {plot.x, plot.y, plot.w, plot.h};
  }
  const std::vector<std::string> labels = distinguishingLabels(app);
  const std::vector<std::string> differs = parameterDifferences(app);
  const auto differsOf = [&](int i) { return i < static_cast<int>(differs.size()) ? differs[static_cast<size_t>(i)] : std::string(); };
  // A pane's caption: in projector mode its one-line label (and the stats on I), else the full caption.
  const auto caption = [&](int i, Rect r, float maxWidth) {
    float top = 0.0f;
    if (app.projector && i < static_cast<int>(labels.size()))
      top = projectorLabel(app, dl, i, labels[static_cast<size_t>(i)], {r.x, r.y, maxWidth, r.h});
    if (!app.projector || app.showStats)
      captionBox(app.overlayRects, dl, r.x, r.y + top, paneCaption(app, i, differsOf(i)), IM_COL32(0, 0, 0, 170), maxWidth);
  };

  if (app.compare.mode == CompareMode::SideBySide) {
    // Each pane's caption lines (none in projector mode: its big labels go on the picture), and the
    // tallest, so that captions above their pictures keep the pictures level.
    std::vector<std::vector<std::string>> captions(static_cast<size_t>(app.paneCount));
    float tallest = 0.0f;
    for (int i = 0; i < app.paneCount && !app.projector; ++i) {
      captions[static_cast<size_t>(i)] = paneCaption(app, i, differsOf(i));
      tallest = std::max(tallest, captionHeight(captions[static_cast<size_t>(i)], cellOf(i, app.paneCount, area).w - 12.0f));
    }
    for (int i = 0; i < app.paneCount; ++i) {
      PaneState& p = app.panes[static_cast<size_t>(i)];
      Rect cell = cellOf(i, app.paneCount, area);
      const float bannerW = cell.w - 12.0f;  // the banner spans the cell, under the picture
      const float cellBottom = cell.y + cell.h;
      cell.h = std::max(cell.h - bannerSpace(app, p, bannerW, 0.3f * cell.h), 1.0f);
      const bool current = imageOnScreen(p);
      const RenderSettings size = app.scene ? renderSettings(app, p) : RenderSettings{};
      const int imageW = current ? p.texture.width() : size.width, imageH = current ? p.texture.height() : size.height;
      const std::vector<std::string>& lines = captions[static_cast<size_t>(i)];
      const PaneLayout layout = layoutPane(cell, imageW, imageH, lines, p.view == PaneView::LightPaths, tallest);
      const Rect r = layout.picture;
      if (current)
        dl->AddImage(p.texture.imguiId(), ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h));
      else
        drawPlaceholder(app, dl, p, r);
      if (current) drawLightPathLabels(app, dl, p, r);
      app.paneRects[static_cast<size_t>(i)] = {r.x, r.y, r.w, r.h};
      const float lh = current && p.texture.legendMax() > 0.0f
                           ? uiPx(34.0f)
                           : 0.0f;
      if (lh > 0.0f) {
        dl->AddRectFilled(ImVec2(r.x, r.y + r.h - lh), ImVec2(r.x + r.w, r.y + r.h),
                          IM_COL32(0, 0, 0, 190));
        app.overlayRects.push_back({r.x, r.y + r.h - lh, r.w, lh});
        drawLegend(dl, {r.x + 6.0f, r.y + r.h - lh + 2.0f, r.w - 12.0f, lh}, p.texture.legendMax(),
                   true);
      }
      if (app.showStructure && app.scene) drawPaneStructure(dl, app, i, r, lh);
      if (app.inspector.pane == i && app.scene) {
        const Camera camera = renderCamera(*app.scene, renderSettings(app, p));
        if (app.inspector.tree) drawRayTree(dl, camera, *app.inspector.tree, app.inspector.highlighted, r.x, r.y, r.w, r.h);
        const float px = r.x + app.inspector.pixel.x / static_cast<float>(camera.width) * r.w;
        const float py = r.y + app.inspector.pixel.y / static_cast<float>(camera.height) * r.h;
        dl->AddCircle(ImVec2(px, py), 6.0f, IM_COL32(255, 0, 255, 255), 16, 2.0f);
      }
      if (layout.captionWidth > 0.0f)
        captionBox(app.overlayRects, dl, layout.captionX, layout.captionY, lines, IM_COL32(0, 0, 0, 170),
                   layout.captionWidth);
      else
        caption(i, r, r.w);
      paneBanners(dl, app, i, r, cell.x + 6.0f, bannerW, cellBottom);
    }
    return;
  }

  const int ia = app.compare.paneA, ib = app.compare.paneB;
  PaneState& a = app.panes[static_cast<size_t>(ia)];
  PaneState& b = app.panes[static_cast<size_t>(ib)];
  const Rect r = compareArea(app, area);
  app.compareRect = {r.x, r.y, r.w, r.h};
  if (app.compare.mode == CompareMode::Wipe) {
    const float split = std::clamp(app.compare.wipe, 0.0f, 1.0f);
    const float sx = r.x + r.w * split;
    if (imageOnScreen(a))
      dl->AddImage(a.texture.imguiId(), ImVec2(r.x, r.y), ImVec2(sx, r.y + r.h), ImVec2(0, 0),
                   ImVec2(split, 1));
    if (imageOnScreen(b))
      dl->AddImage(b.texture.imguiId(), ImVec2(sx, r.y), ImVec2(r.x + r.w, r.y + r.h),
                   ImVec2(split, 0), ImVec2(1, 1));
    dl->AddLine(ImVec2(sx, r.y), ImVec2(sx, r.y + r.h), IM_COL32(255, 255, 255, 230), 2.0f);
    const float handle = uiPx(7.0f);
    dl->AddCircleFilled(ImVec2(sx, r.y + r.h / 2), handle, IM_COL32_WHITE);
    app.overlayRects.push_back({sx - handle - 1, r.y, 2 * handle + 2, r.h});
    app.paneRects[static_cast<size_t>(ia)] = {r.x, r.y, sx - r.x, r.h};
    app.paneRects[static_cast<size_t>(ib)] = {sx, r.y, r.x + r.w - sx, r.h};
    caption(ia, r, r.w / 2);
    if (app.projector) {
      caption(ib, {r.x + r.w / 2, r.y, r.w / 2, r.h}, r.w / 2);
    } else {
      const auto lines = paneCaption(app, ib, differsOf(ib));
      float bw = 0;
      for (const auto& l : lines) bw = std::max(bw, ImGui::CalcTextSize(l.c_str()).x + 8.0f);
      bw = std::min(bw, r.w / 2);
      captionBox(app.overlayRects, dl, r.x + r.w - bw, r.y, lines, IM_COL32(0, 0, 0, 170), bw);
    }
    paneBanners(dl, app, ia, {r.x, r.y, r.w / 2, r.h}, r.x, r.w / 2, area.y + area.h);
    paneBanners(dl, app, ib, {r.x + r.w / 2, r.y, r.w / 2, r.h}, r.x + r.w / 2, r.w / 2, area.y + area.h);
    return;
  }

  // Difference heatmap of A against B (made by refreshPanes in the background), with its legend
  // below.
  const bool diffCurrent = app.diff.valid && app.diff.panes[0] == ia && app.diff.panes[1] == ib;
  if (diffCurrent) {
    dl->AddImage(app.diff.texture.imguiId(), ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h));
    drawLegend(dl, {r.x, r.y + r.h + 6.0f, r.w, 30.0f}, app.diff.usedMax,
               app.diff.requestedMax <= 0);
  }
  // Each pane named by what tells it apart ("bvh", "path, 64 spp"; pane_labels.h), not always the technique:
  // "A (raycast) against B (raycast)" said nothing when the panes differ in their accelerator.
  const auto named = [&](int i, const PaneState& p) {
    std::string what = static_cast<size_t>(i) < labels.size() ? labels[static_cast<size_t>(i)].substr(3) : p.technique;
    for (size_t at = what.find("  "); at != std::string::npos; at = what.find("  ", at)) what.replace(at, 2, ", ");
    return std::string(1, paneLetter(i)) + " (" + what + ")";
  };
  std::vector<std::string> lines{std::string(app.compare.diff == DiffMode::Absolute ? "absolute" : "relative") +
                                 " error of " + named(ia, a) + "  against " + named(ib, b)};
  if (!diffCurrent) lines.emplace_back("waiting for both images...");
  captionBox(app.overlayRects, dl, r.x, r.y, lines, IM_COL32(0, 0, 0, 170), r.w);
}

}  // namespace

void handleCameraInput(AppState& app, GLFWwindow* window, float x, float y, float w, float h) {
  ImGuiIO& io = ImGui::GetIO();
  const Rect area{x, y, w, h};
  bool& dragging = app.draggingView;
  const bool anyDown = ImGui::IsMouseDown(0) || ImGui::IsMouseDown(1) || ImGui::IsMouseDown(2);
  if (!anyDown) {
    dragging = false;
    app.draggingWipe = false;
  }
  if (!io.WantCaptureMouse) {
    const bool clicked =
        ImGui::IsMouseClicked(0) || ImGui::IsMouseClicked(1) || ImGui::IsMouseClicked(2);
    if (clicked && area.contains(io.MousePos)) {
      dragging = true;
      if (app.compare.mode == CompareMode::Wipe && ImGui::IsMouseClicked(0)) {
        const auto& cr = app.compareRect;
        const float sx = cr[0] + cr[2] * app.compare.wipe;
        app.draggingWipe = cr[2] > 0 && std::abs(io.MousePos.x - sx) < uiPx(10.0f);
      }
    }
    const float cellH = std::max(app.paneCount == 4 ? h / 2 : h, 1.0f);
    // The frame a drag starts contributes no motion: the pointer may have jumped there.
    const bool moving =
        dragging && !clicked && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f);
    if (moving) {
      if (app.draggingWipe) {
        const auto& cr = app.compareRect;
        if (cr[2] > 0) app.compare.wipe = std::clamp((io.MousePos.x - cr[0]) / cr[2], 0.0f, 1.0f);
      } else if (ImGui::IsMouseDown(0)) {
        orbit(app.camera, io.MouseDelta.x * 0.005f, io.MouseDelta.y * 0.005f);
        app.cameraChanged = true;
      } else {
        pan(app.camera, -io.MouseDelta.x / cellH, io.MouseDelta.y / cellH);
        app.cameraChanged = true;
      }
    }
    // A click on a pane's task banner unfolds or folds it.
    if (ImGui::IsMouseReleased(0) && io.MouseDragMaxDistanceSqr[0] < 9.0f)
      for (int i = 0; i < kMaxPanes; ++i) {
        const auto it = app.widgetRects.find(std::string("pane.") + paneLetter(i) + ".banner");
        if (it == app.widgetRects.end()) continue;
        const auto& br = it->second;
        const ImVec2 m = io.MousePos;
        if (m.x >= br[0] && m.y >= br[1] && m.x < br[0] + br[2] && m.y < br[1] + br[3])
          app.panes[static_cast<size_t>(i)].bannerOpen = !app.panes[static_cast<size_t>(i)].bannerOpen;
      }
    // A click without a drag on a pane's image (side by side) selects that pixel for the ray-tree inspector.
    if (ImGui::IsMouseReleased(0) && io.MouseDragMaxDistanceSqr[0] < 9.0f && !app.draggingWipe &&
        app.compare.mode == CompareMode::SideBySide && app.scene)
      for (int i = 0; i < app.paneCount; ++i) {
        const auto& pr = app.paneRects[static_cast<size_t>(i)];
        const ImVec2 m = io.MousePos;
        if (pr[2] <= 0 || m.x < pr[0] || m.y < pr[1] || m.x >= pr[0] + pr[2] || m.y >= pr[1] + pr[3]) continue;
        const RenderSettings s = renderSettings(app, app.panes[static_cast<size_t>(i)]);
        inspectPixel(app, i,
                     Vec2(std::floor((m.x - pr[0]) / pr[2] * static_cast<float>(s.width)) + 0.5f,
                          std::floor((m.y - pr[1]) / pr[3] * static_cast<float>(s.height)) + 0.5f));
      }
    if (io.MouseWheel != 0.0f && area.contains(io.MousePos)) {
      zoom(app.camera, std::pow(0.85f, io.MouseWheel));
      app.cameraChanged = true;
    }
  }
  if (!io.WantCaptureKeyboard && app.scene) {
    Vec3 move(0.0f);
    const auto key = [&](int k) { return glfwGetKey(window, k) == GLFW_PRESS ? 1.0f : 0.0f; };
    move.x = key(GLFW_KEY_D) - key(GLFW_KEY_A);
    move.y = key(GLFW_KEY_E) - key(GLFW_KEY_Q);
    move.z = key(GLFW_KEY_W) - key(GLFW_KEY_S);
    if (move != Vec3(0.0f)) {
      const float speed = 0.25f * app.scene->geometry.sceneBounds().diagonal() *
                          (key(GLFW_KEY_LEFT_SHIFT) + key(GLFW_KEY_RIGHT_SHIFT) > 0 ? 4.0f : 1.0f);
      fly(app.camera, move * speed * io.DeltaTime);
      app.cameraChanged = true;
    }
  }
}

std::vector<std::string> wrapCaption(const std::vector<std::string>& lines, float width) {
  const TextWidth measure = [](std::string_view t) { return ImGui::CalcTextSize(t.data(), t.data() + t.size()).x; };
  std::vector<std::string> wrapped;
  for (const std::string& l : lines)
    for (std::string& part : wrapCaptionLine(l, width, measure)) wrapped.push_back(std::move(part));
  return wrapped;
}

}  // namespace ll::gui
