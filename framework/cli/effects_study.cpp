// lightlab study effects --out DIR [--scenes a.json,b.json] [--tolerance R] [--width W] [--reference-spp N]
//
// For each scene: the measured effect shares (modules/effects_measurement.h),
// then every CPU technique rendered at W pixels and compared with a
// path-traced ground truth -- its real error against its real time -- beside
// what the probe predicted from the classes it misses. Writes DIR/effects.csv
// and DIR/effects.html (a table and an error-against-time plot per scene).
#include "cli/effects_study.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "cli/study_stubs.h"
#include "core/error.h"
#include "core/markup.h"
#include "core/progress.h"
#include "core/timer.h"
#include "metrics/error_plot.h"
#include "metrics/image_metrics.h"
#include "modules/effects_measurement.h"
#include "modules/registry.h"
#include "render/render_job.h"
#include "scene/scene_loader.h"

namespace ll::cli {

namespace fs = std::filesystem;

namespace {

struct TechniqueRun {
  std::string technique;
  int passes = 1;
  double seconds = 0.0;    // measured: preparation + render, at the study's size
  double cameraSeconds = 0.0;  // the camera's picture: preparation + render x the ratio of pixels
  double relmse = 0.0;     // against the ground truth
  double predicted = 0.0;  // the probe's relMSE of the classes it misses
  bool unmeasured = false;  // misses an effect that is no light-path class
};

struct SceneResult {
  std::string scene;
  EffectsReport report;
  double truthSeconds = 0.0;
  std::vector<TechniqueRun> runs;
  int winner = -1;  // index in runs: the fastest whose real error is within the tolerance
};

// Renders `technique` (its verdict's parameters) at width x height with `spp` passes; the seconds of its
// preparation and of its passes.
Image render(const Scene& scene, const Accelerator& accel, const std::string& technique, int width, int height,
             int spp, uint64_t seed, double* prepareSeconds, double* renderSeconds, StudyStubs& stubs) {
  const std::string name = technique.substr(0, technique.find(' '));
  const TechniqueInfo& t = findTechnique(name);
  ParamSet params(t.name, t.params);
  if (params.has("intersection")) params.set("intersection", "framework");
  if (technique.find("spectral=true") != std::string::npos) params.set("spectral", "true");
  const auto instance = t.make();
  RenderSettings rs;
  rs.width = width;
  rs.height = height;
  rs.spp = spp;
  rs.seed = seed;
  RenderJob job(scene, accel, *instance, params, rs);
  job.run();
  stubs.add(job.stats().missingTasks);
  *prepareSeconds = job.stats().prepareSeconds;
  *renderSeconds = job.stats().renderSeconds;
  return job.frame().resolve(false);
}

std::string shortNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Index in r.runs of the fastest run (time for the camera's picture) whose real error is within `tolerance`.
int fastestWithin(const SceneResult& r, double tolerance) {
  int best = -1;
  for (size_t k = 0; k < r.runs.size(); ++k)
    if (r.runs[k].relmse <= tolerance &&
        (best < 0 || r.runs[k].cameraSeconds < r.runs[static_cast<size_t>(best)].cameraSeconds))
      best = static_cast<int>(k);
  return best;
}

std::string runText(const SceneResult& r, int k) {
  if (k < 0) return "none within the tolerance";
  const TechniqueRun& w = r.runs[static_cast<size_t>(k)];
  return w.technique + " at " + std::to_string(w.passes) + (w.passes == 1 ? " pass" : " passes");
}

std::string winnerText(const SceneResult& r) { return runText(r, r.winner); }

// The study's tolerance and two looser ones: where the winners part ways.
std::vector<double> winnerTolerances(double tolerance) { return {tolerance, 10.0 * tolerance, 100.0 * tolerance}; }

std::string html(const std::vector<SceneResult>& results, double tolerance) {
  std::string h = "<!doctype html><meta charset=utf-8><title>LightLab: the effects each scene calls for</title>"
                  "<style>body{font:15px sans-serif;max-width:1100px;margin:2em auto}td,th{padding:2px 10px;"
                  "text-align:right}td:first-child,th:first-child{text-align:left}.win{font-weight:bold}</style>"
                  "<h1>Which effects does each scene call for, and which technique is cheapest?</h1>"
                  "<p>Each technique rendered once (path: enough passes for its noise to fall within the tolerance), "
                  "its error measured against path-traced ground truth (relMSE), beside the probe's prediction: "
                  "the relMSE of the light-path classes the technique misses. Tolerance relMSE " +
                  std::to_string(tolerance) + ". Bold: the fastest within it.</p>";
  for (const SceneResult& r : results) {
    h += "<h2>" + escapeMarkup(r.scene, true) + "</h2><p>Effect shares (probe " + std::to_string(r.report.width) + "x" +
         std::to_string(r.report.height) + ", " + std::to_string(r.report.spp) + " spp): ";
    bool first = true;
    for (const EffectMeasurement& m : r.report.effects) {
      if (!m.measured || m.share.high <= 0.0) continue;
      char buf[128];
      std::snprintf(buf, sizeof buf, "%s%s %.2f %% (relMSE without %.2g)", first ? "" : ", ", effectName(m.effect),
                    100.0 * m.share.value, m.relMseWithout.value);
      h += escapeMarkup(buf, true);
      first = false;
    }
    h += "</p><table><tr><th>technique</th><th>passes</th><th>seconds here</th><th>seconds at the camera's "
         "size</th><th>relMSE vs ground truth</th><th>predicted (misses)</th></tr>";
    std::vector<PlotSeries> series;
    for (size_t k = 0; k < r.runs.size(); ++k) {
      const TechniqueRun& run = r.runs[k];
      char buf[256];
      std::snprintf(buf, sizeof buf, "<td>%d</td><td>%.3g</td><td>%.3g</td><td>%.3g</td><td>%.3g%s</td>", run.passes,
                    run.seconds, run.cameraSeconds, run.relmse, run.predicted, run.unmeasured ? " + unmeasured" : "");
      h += std::string("<tr") + (static_cast<int>(k) == r.winner ? " class=win" : "") + "><td>" +
           escapeMarkup(run.technique, true) + "</td>" + buf + "</tr>";
      if (series.empty() || series.back().name != run.technique) series.push_back({run.technique, {}});
      series.back().points.push_back({run.cameraSeconds, std::max(run.relmse, 1e-7), std::to_string(run.passes)});
    }
    h += "</table>";
    h += logLogSvg(series, r.scene + ": error against time", "seconds at the camera's size", "relMSE vs ground truth",
                   560, 360);
    h += "<p>Winner: " + escapeMarkup(winnerText(r), true) +
         "; predicted by the probe: " +
         escapeMarkup(r.report.cheapest ? *r.report.cheapest : "none", true) + ".</p>";
  }
  h += "<h2>The fastest technique within each tolerance</h2><table><tr><th>scene</th>";
  for (double t : winnerTolerances(tolerance)) h += "<th>relMSE " + shortNumber(t) + "</th>";
  h += "</tr>";
  for (const SceneResult& r : results) {
    h += "<tr><td>" + escapeMarkup(r.scene, true) + "</td>";
    for (double t : winnerTolerances(tolerance)) h += "<td>" + escapeMarkup(runText(r, fastestWithin(r, t)), true) + "</td>";
    h += "</tr>";
  }
  h += "</table>";
  return h;
}

}  // namespace

void runEffectsStudy(const EffectsStudyOptions& o, bool quiet) {
  std::vector<std::string> scenes = o.scenes;
  if (scenes.empty())
    for (const char* s : {"whitted_1980", "cornell_box", "cornell_box_point_light", "glass_and_water",
                          "metal_spheres", "metal_spheres_sky", "prism", "textured_floor"})
      scenes.push_back(std::string(LIGHTLAB_SOURCE_DIR) + "/data/scenes/" + s + ".json");
  std::error_code ec;
  fs::create_directories(o.out, ec);
  if (ec) throwUserError("study effects: cannot create " + o.out + ": " + ec.message());
  setPrecomputationCache(false);  // each render's time includes its own precomputation (radiosity's solve)

  std::vector<SceneResult> results;
  ProgressBar bar("study effects", static_cast<double>(scenes.size()), quiet);
  StudyStubs stubs;
  for (size_t si = 0; si < scenes.size(); ++si) {
    const Scene scene = loadScene(scenes[si]);
    const AcceleratorInfo& a = findAccelerator("bvh");
    const auto accel = buildAccelerator(a, ParamSet(a.name, a.params), scene.geometry);
    SceneResult r;
    r.scene = fs::path(scenes[si]).filename().string();
    LightPathProbeSettings ps;
    ps.width = o.width;
    r.report = measureSceneEffects(scene, *accel, o.tolerance, ps, [&](const std::string&, double f) {
      bar.update(static_cast<double>(si) + 0.3 * f);
    });
    const int width = r.report.width, height = r.report.height;
    double prepare = 0.0, passes = 0.0;
    const Image truth =
        render(scene, *accel, r.report.probeTechnique, width, height, o.referenceSpp, 1000003, &prepare, &passes, stubs);
    r.truthSeconds = prepare + passes;
    const double pixelRatio = static_cast<double>(scene.camera.width) * static_cast<double>(scene.camera.height) /
                              (static_cast<double>(width) * static_cast<double>(height));
    for (size_t k = 0; k < r.report.techniques.size(); ++k) {
      const TechniqueVerdict& v = r.report.techniques[k];
      bar.update(static_cast<double>(si) + 0.3 + 0.7 * static_cast<double>(k) / r.report.techniques.size());
      // Passes: anti-aliasing for the deterministic techniques; for path up to the passes the probe says bring
      // its noise within half the tolerance (at most a quarter of the truth's, which must stay far less noisy).
      std::vector<int> counts{1, 4, 16};
      if (v.technique.rfind("path", 0) == 0) {
        counts = {16, 64, 256};
        counts.push_back(std::min(v.passes, o.referenceSpp / 4));
        std::sort(counts.begin(), counts.end());
        counts.erase(std::unique(counts.begin(), counts.end()), counts.end());
        counts.erase(std::remove_if(counts.begin(), counts.end(), [&](int c) { return c > o.referenceSpp / 4; }),
                     counts.end());
      }
      for (int count : counts) {
        TechniqueRun run;
        run.technique = v.technique;
        run.passes = count;
        const Image image = render(scene, *accel, v.technique, width, height, count, 1, &prepare, &passes, stubs);
        run.seconds = prepare + passes;
        run.cameraSeconds = prepare + passes * pixelRatio;
        run.relmse = compareImages(image, truth).relmse;
        run.predicted = v.missedError.value;
        run.unmeasured = !v.missedUnmeasured.empty();
        r.runs.push_back(run);
      }
    }
    r.winner = fastestWithin(r, o.tolerance);
    results.push_back(std::move(r));
    bar.update(static_cast<double>(si + 1));
  }
  bar.finish();

  const std::string csvPath = (fs::path(o.out) / "effects.csv").string();
  std::ofstream csv(csvPath);
  if (!csv) throwUserError("study effects: cannot write " + csvPath);
  csv << "scene,technique,passes,seconds,seconds_at_camera_size,relmse_vs_ground_truth,predicted_relmse_of_missed_classes,"
         "misses_unmeasured,winner\n";
  for (const SceneResult& r : results)
    for (size_t k = 0; k < r.runs.size(); ++k) {
      const TechniqueRun& run = r.runs[k];
      csv << r.scene << ',' << run.technique << ',' << run.passes << ',' << run.seconds << ',' << run.cameraSeconds
          << ',' << run.relmse << ',' << run.predicted << ',' << (run.unmeasured ? 1 : 0) << ','
          << (static_cast<int>(k) == r.winner ? 1 : 0) << '\n';
    }
  const std::string htmlPath = (fs::path(o.out) / "effects.html").string();
  std::ofstream page(htmlPath);
  if (!page) throwUserError("study effects: cannot write " + htmlPath);
  std::string text = html(results, o.tolerance);
  text.insert(text.find("</h1>") + 5, stubs.html());  // under the title, where it is read
  page << text;

  for (const SceneResult& r : results) {
    std::printf("%s: ", r.scene.c_str());
    for (const EffectMeasurement& m : r.report.effects)
      if (m.measured && m.share.high > 0.0)
        std::printf("%s %.1f %% ", effectName(m.effect), 100.0 * m.share.value);
    std::printf("\n  %-26s %8s %10s %12s %12s %12s\n", "technique", "passes", "seconds", "at camera", "relMSE",
                "predicted");  // seconds at the study's size, and estimated for the camera's
    for (size_t k = 0; k < r.runs.size(); ++k) {
      const TechniqueRun& run = r.runs[k];
      std::printf("  %-26s %8d %10.3g %12.3g %12.3g %12.3g%s%s\n", run.technique.c_str(), run.passes, run.seconds,
                  run.cameraSeconds, run.relmse, run.predicted, run.unmeasured ? " (+ unmeasured)" : "",
                  static_cast<int>(k) == r.winner ? "  <- winner" : "");
    }
    std::printf("  winner within relMSE %g: %s (the probe predicted %s)\n", o.tolerance, winnerText(r).c_str(),
                r.report.cheapest ? r.report.cheapest->c_str() : "none");
  }
  std::printf("\nthe fastest technique within each tolerance (relMSE against ground truth, time for the camera's picture):\n");
  std::printf("  %-28s", "scene");
  for (double t : winnerTolerances(o.tolerance)) std::printf(" %-30s", ("relMSE " + shortNumber(t)).c_str());
  std::printf("\n");
  for (const SceneResult& r : results) {
    std::printf("  %-28s", r.scene.c_str());
    for (double t : winnerTolerances(o.tolerance)) std::printf(" %-30s", runText(r, fastestWithin(r, t)).c_str());
    std::printf("\n");
  }
  std::printf("wrote %s and %s\n", csvPath.c_str(), htmlPath.c_str());
  stubs.print();
}

}  // namespace ll::cli
