#include "preset/preset_render.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/timer.h"
#include "metrics/image_metrics.h"
#include "modules/registry.h"
#include "render/cost_image.h"
#include "render/light_path_mosaic.h"
#include "render/render_job.h"
#include "scene/scene_loader.h"

namespace ll {

namespace {

constexpr int kGap = 4;  // pixels between side-by-side panes

// The pane indices the compare mode shows, in drawing order.
std::vector<int> shownPanes(const ViewPreset& p) {
  if (p.compare.mode != CompareMode::SideBySide) return {p.compare.paneA, p.compare.paneB};
  std::vector<int> panes;
  for (int i = 0; i < p.paneCount; ++i) panes.push_back(i);
  return panes;
}

ParamSet paramsOf(const std::string& owner, const std::vector<ParamDecl>& decls,
                  const std::map<std::string, std::string>& values) {
  ParamSet set(owner, decls);
  for (const auto& [name, value] : values) set.set(name, value);
  return set;
}

// One pane as the GUI shows it: the linear image times 2^exposure, or the cost heatmap.
Image renderPane(const Scene& scene, const PaneSetup& pane, const RenderSettings& settings, float exposure,
                 PresetFigure& figure, const std::function<void(int, int)>& onPass) {
  const TechniqueInfo& t = findTechnique(pane.technique);
  const AcceleratorInfo& a = findAccelerator(pane.accelerator);
  const ParamSet accelParams = paramsOf("accelerator '" + a.name + "'", a.params, pane.accelParams);
  const auto accel = buildAccelerator(a, accelParams, scene.geometry);
  if (pane.view == "nodes" || pane.view == "primitives") {
    const CostMetric metric = pane.view == "nodes" ? CostMetric::NodesVisited : CostMetric::PrimitivesTested;
    onPass(1, 1);
    return costHeatmap(accelCostImage(*accel, renderCamera(scene, settings), metric), 0.0f, nullptr);
  }
  const ParamSet params = paramsOf("technique '" + t.name + "'", t.params, pane.techniqueParams);
  const auto technique = t.make();
  RenderSettings jobSettings = settings;
  jobSettings.lightPaths = pane.view == "light-paths";
  RenderJob job(scene, *accel, *technique, params, jobSettings);
  job.run(onPass);
  for (const auto& [id, what] : job.stats().missingTasks) figure.missingTasks[id] = what;
  Image image = job.frame().resolve();
  if (jobSettings.lightPaths && job.frame().keepsLightPaths()) {
    LightPathMosaic mosaic = fitMosaic(lightPathMosaic(job.frame()), settings.width, settings.height);
    image = std::move(mosaic.image);
    std::string note = pane.technique + " split by light path, left to right and top to bottom:";
    for (size_t k = 0; k < mosaic.tiles.size(); ++k) note += (k ? ", " : " ") + mosaic.tiles[k].label();
    figure.notes.push_back(note);
  }
  const float scale = std::exp2(exposure);
  for (Rgb& c : image.pixels()) c = c * scale;
  return image;
}

void blit(const Image& src, Image& dst, int x0, int y0) {
  for (int y = 0; y < src.height(); ++y)
    for (int x = 0; x < src.width(); ++x) dst.at(x0 + x, y0 + y) = src.at(x, y);
}

}  // namespace

bool presetNeedsGpu(const ViewPreset& preset) {
  for (int i : shownPanes(preset))
    if (findTechnique(preset.panes.at(static_cast<size_t>(i)).technique).gpu) return true;
  return false;
}

PresetFigure renderPresetFigure(const ViewPreset& preset, const FigureLimits& limits,
                                const std::function<void(double)>& onProgress) {
  const Timer timer;
  PresetFigure figure;
  const Scene scene = loadScene(preset.scene);

  RenderSettings base;
  base.width = preset.width > 0 ? preset.width : scene.camera.width;
  base.height = preset.height > 0 ? preset.height : scene.camera.height;
  if (limits.maxWidth > 0 && base.width > limits.maxWidth) {
    base.height = std::max(1, base.height * limits.maxWidth / base.width);
    base.width = limits.maxWidth;
  }
  base.camera = preset.camera;
  figure.paneWidth = base.width;
  figure.paneHeight = base.height;

  const std::vector<int> shown = shownPanes(preset);
  std::vector<Image> images;
  for (size_t k = 0; k < shown.size(); ++k) {
    const PaneSetup& pane = preset.panes.at(static_cast<size_t>(shown[k]));
    RenderSettings settings = base;
    settings.spp = limits.maxSpp > 0 ? std::min(pane.spp, limits.maxSpp) : pane.spp;
    images.push_back(renderPane(scene, pane, settings, preset.exposure, figure, [&](int done, int total) {
      if (onProgress)
        onProgress((static_cast<double>(k) + static_cast<double>(done) / std::max(total, 1)) /
                   static_cast<double>(shown.size()));
    }));
  }

  const int w = base.width, h = base.height;
  switch (preset.compare.mode) {
    case CompareMode::Difference:
      figure.image = differenceHeatmap(images[0], images[1], preset.compare.diff, preset.compare.diffMax);
      break;
    case CompareMode::Wipe: {
      figure.image = images[1];
      const int split = std::clamp(static_cast<int>(std::lround(preset.compare.wipe * static_cast<float>(w))), 0, w);
      for (int y = 0; y < h; ++y) {
        for (int x = 0; x < split; ++x) figure.image.at(x, y) = images[0].at(x, y);
        if (split > 0 && split < w) figure.image.at(split, y) = Rgb(1.0f);  // the split line
      }
      break;
    }
    case CompareMode::SideBySide: {
      const int n = static_cast<int>(images.size());
      const int cols = n == 4 ? 2 : n, rows = n == 4 ? 2 : 1;
      figure.image = Image(cols * w + (cols - 1) * kGap, rows * h + (rows - 1) * kGap, Rgb(1.0f));
      for (int i = 0; i < n; ++i) blit(images[static_cast<size_t>(i)], figure.image, (i % cols) * (w + kGap), (i / cols) * (h + kGap));
      break;
    }
  }
  figure.seconds = timer.seconds();
  return figure;
}

}  // namespace ll
