// lightlab render SCENE [-t TECHNIQUE] [-a ACCEL] [--width W --height H]
//                [--spp N] [--seed S] [--set name=value ...] -o OUT [--stats FILE]
#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/scene_setup.h"
#include "cli/task_lines.h"
#include "core/error.h"
#include "core/files.h"
#include "core/progress.h"
#ifdef LIGHTLAB_HAVE_GUI
#include "gpu/offscreen_gl.h"
#endif
#include "render/cost_image.h"
#include "render/light_path_mosaic.h"
#include "render/render_job.h"

namespace ll::cli {

namespace fs = std::filesystem;

namespace {
struct RenderOptions {
  std::string scene, technique = "raycast", accelerator = "none", output, statsPath;
  int width = 0, height = 0, spp = 1;
  uint64_t seed = 0;
  float exposure = 0.0f;
  std::vector<std::string> sets;
  std::string cost;  // "", nodes or primitives
};
}  // namespace

Command addRenderCommand(CLI::App& app, const GlobalOptions& global) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to an image file");
  cmd->add_option("scene", o->scene, "Scene file (.json or .obj)")->required();
  cmd->add_option("-t,--technique", o->technique, "Rendering technique (see `lightlab info --list`)")
      ->capture_default_str();
  cmd->add_option("-a,--accel", o->accelerator, "Accelerator for ray queries")->capture_default_str();
  cmd->add_option("--width", o->width, "Image width in pixels (default: the scene camera's)")
      ->check(CLI::Range(1, 16384));
  cmd->add_option("--height", o->height, "Image height in pixels (default: the scene camera's)")
      ->check(CLI::Range(1, 16384));
  cmd->add_option("--spp", o->spp, "Samples per pixel (stratified; 1 = pixel centre)")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  cmd->add_option("--seed", o->seed, "Seed of the random streams (images depend on it, not on threads)")
      ->capture_default_str();
  cmd->add_option("--set", o->sets, "Technique or accelerator parameter, name=value (repeatable)");
  cmd->add_option("-o,--output", o->output,
                  "Output image: .png, .jpg (sRGB), .hdr or .pfm (linear); default out/SCENE-TECHNIQUE.png");
  cmd->add_option("--exposure", o->exposure, "Exposure in stops for .png/.jpg output")->capture_default_str();
  cmd->add_option("--stats", o->statsPath, "Write statistics (times, rays by kind, ...) as JSON");
  cmd->add_option("--cost", o->cost,
                  "Instead of the image: the accelerator's cost per pixel for the camera ray, as a heatmap "
                  "(.png/.jpg, 99th-percentile scale) or raw counts (.pfm/.hdr)")
      ->check(CLI::IsMember({"nodes", "primitives"}));
  return [o, &global]() {
    SceneSetup s = setUpScene(o->scene, o->technique, o->accelerator, o->sets);
    if (o->output.empty())  // out/ in the working directory (git ignores it), the path printed below
      o->output = (fs::path("out") / (fs::path(o->scene).stem().string() + "-" + s.technique->name +
                                      (o->cost.empty() ? "" : "-cost-" + o->cost) + ".png")).string();
    RenderSettings settings;
    settings.width = o->width > 0 ? o->width : s.scene.camera.width;
    settings.height = o->height > 0 ? o->height : s.scene.camera.height;
    if (o->width > 0 && o->height == 0)  // keep the camera's aspect ratio
      settings.height = std::max(1, o->width * s.scene.camera.height / s.scene.camera.width);
    if (o->height > 0 && o->width == 0)
      settings.width = std::max(1, o->height * s.scene.camera.width / s.scene.camera.height);
    settings.spp = o->spp;
    settings.seed = o->seed;
    settings.lightPaths = !o->statsPath.empty();  // `path` splits its estimate by light-path class for the stats

    if (!o->cost.empty()) {
      Camera camera = renderCamera(s.scene, settings);
      const CostMetric metric = o->cost == "nodes" ? CostMetric::NodesVisited : CostMetric::PrimitivesTested;
      const Image counts = accelCostImage(*s.accel, camera, metric);
      const std::string ext = std::filesystem::path(o->output).extension().string();
      float scale = 0.0f;
      if (ext == ".pfm" || ext == ".hdr")
        saveImage(counts, o->output);
      else
        saveImage(costHeatmap(counts, 0.0f, &scale), o->output);
      double sum = 0.0, max = 0.0;
      for (const Rgb& c : counts.pixels()) {
        sum += static_cast<double>(c.r);
        max = std::max(max, static_cast<double>(c.r));
      }
      std::printf("wrote %s (%s per camera ray, accelerator %s: mean %.2f, max %.0f%s)\n", o->output.c_str(),
                  o->cost == "nodes" ? "nodes visited" : "primitives tested", s.accelInfo->name.c_str(),
                  sum / static_cast<double>(counts.pixelCount()), max,
                  scale > 0 ? (", colour scale 0-" + std::to_string(static_cast<int>(scale))).c_str() : "");
      return;
    }
#ifdef LIGHTLAB_HAVE_GUI
    if (s.technique->gpu) gpu::OffscreenGl::createForCommandLine();
#endif
    const auto technique = s.technique->make();
    RenderJob job(s.scene, *s.accel, *technique, s.techniqueParams, settings);
    ProgressBar bar("render " + o->technique, 1.0, global.quiet);
    job.run([&](int done, int total) { bar.update(static_cast<double>(done) / total); });
    bar.finish();

    RenderStats& stats = job.stats();
    stats.scene = o->scene;
    stats.technique = s.technique->name;
    stats.accelerator = s.accelInfo->name;
    stats.loadSeconds = s.loadSeconds;
    stats.buildSeconds = s.buildSeconds;
    stats.accel.buildSeconds = s.buildSeconds;

    saveImage(job.frame().resolve(), o->output, ToneMap{o->exposure});
    // Each light-path class beside the output (OUT.direct-lighting.png, ...), and its share.
    std::string classLine;
    for (const LightPathShare& c : stats.lightPaths) {
      const fs::path out(o->output);
      const fs::path file = out.parent_path() / (out.stem().string() + "." + lightPathClassName(c.cls) +
                                                 out.extension().string());
      saveImage(job.frame().resolveLightPath(c.cls), file.string(), ToneMap{o->exposure});
      char part[96];
      std::snprintf(part, sizeof part, "%s%s %.1f %%", classLine.empty() ? "" : ", ", lightPathClassName(c.cls),
                    100.0 * c.luminanceShare);
      classLine += part;
    }
    if (!stats.lightPaths.empty()) {  // and all of them side by side: OUT.light-paths.png
      const fs::path out(o->output);
      saveImage(lightPathMosaic(job.frame()).image,
                (out.parent_path() / (out.stem().string() + ".light-paths" + out.extension().string())).string(),
                ToneMap{o->exposure});
    }
    if (!o->statsPath.empty()) {
      createParentDirectory(o->statsPath);
      std::ofstream out(o->statsPath);
      if (!out) throwUserError(o->statsPath + ": cannot write statistics file");
      out << stats.toJson().dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    }
    const bool striped = !stats.missingTasks.empty() && job.frame().anyStub();  // one scan of the frame
    printTaskLines(stats.missingTasks, stats.exactFallbacks, striped, stats.taskViolations, stats.referenceTasks);
    if (s.technique->ignoresLightsOf(s.scene))
      std::fprintf(stderr, "lightlab: %s lights the scene by its emissive surfaces only; the scene's %zu point or "
                   "directional light(s) light nothing here (give an object \"emission\" for an area light)\n",
                   s.technique->name.c_str(), s.scene.lights.size());
    if (stats.work.nonFinite > 0)
      std::fprintf(stderr, "lightlab: %llu NaN/Inf samples were replaced by black\n",
                   static_cast<unsigned long long>(stats.work.nonFinite));
    // Rasterizers trace no rays: their speed is the frame time alone.
    char speed[64] = "";
    if (stats.work.totalRays() > 0)
      std::snprintf(speed, sizeof speed, ", %.2f Mrays/s",
                    static_cast<double>(stats.work.totalRays()) / std::max(stats.renderSeconds, 1e-9) * 1e-6);
    std::printf("wrote %s (%dx%d, %d spp, %s, %.3f s render%s)\n", o->output.c_str(), settings.width,
                settings.height, settings.spp, s.technique->name.c_str(), stats.renderSeconds, speed);
    if (!classLine.empty())
      std::printf("light paths (share of the luminance; one image each, and all side by side in .light-paths, beside %s): %s\n", o->output.c_str(),
                  classLine.c_str());
    if (stats.skipped) {
      const SkippedWork& w = *stats.skipped;
      // Timed on the probe (path), or counted by the technique (radiosity's rows), or nothing saved.
      std::string saved = w.saved.empty() ? "no time saved" : w.saved;
      if (w.secondsPerPassSkipping > 0.0 && w.secondsPerPassFull > 0.0) {
        const double fraction = 1.0 - w.secondsPerPassSkipping / w.secondsPerPassFull;
        char text[128];
        if (fraction >= 0.05)
          std::snprintf(text, sizeof text, "%.0f %% less time per sample (measured on the probe)", 100.0 * fraction);
        else  // within the timing noise of a small probe
          std::snprintf(text, sizeof text, "no measurable time saved (%.2g against %.2g s per sample on the probe)",
                        w.secondsPerPassSkipping, w.secondsPerPassFull);
        saved = text;
      }
      char bound[64] = "";  // a probe's estimate has an interval; a measured or estimated value has none
      if (w.errorAddedHigh != w.errorAdded) std::snprintf(bound, sizeof bound, "95 %% bound %.2g, ", w.errorAddedHigh);
      char probing[48] = "";
      if (w.probeSeconds > 0.0) std::snprintf(probing, sizeof probing, "; %.1f s of probing", w.probeSeconds);
      std::printf("effects=measured: left out %s; error added relMSE %.2g (%stolerance %.2g); %s%s\n",
                  w.skipped.c_str(), w.errorAdded, bound, w.tolerance, saved.c_str(), probing);
    }
  };
}

}  // namespace ll::cli
