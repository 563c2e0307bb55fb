// lightlab study SCENE --knob NAME=v1,v2,... [-t TECH[,TECH...]] [-a ACCEL] [--set name=value ...]
//                [--width W --height H] [--spp N] [--seed S]
//                [--reference IMG | --reference-technique T --reference-spp N --reference-set name=value ...]
//                --out DIR
// lightlab study BUILTIN --out DIR   (raycast-spp, whitted-depth, radiosity-patch-size, ...: see --help)
// What accuracy costs in time: renders the scene once per knob value (and per
// technique), times each (accelerator build + render, seconds of wall time),
// measures its error against a reference, and writes DIR/study.csv, the
// images, and DIR/study.html (error against time, log-log, with the images).
// The knob is any technique or accelerator parameter, "spp", or "accel" (the
// accelerator's name). The reference is an image file, or rendered once
// (DIR/reference.pfm) by the reference technique (default: the first one) at
// --reference-spp samples (default: 256 if the knob is spp, else --spp) with
// the --reference-set changes (for example light_samples=1024), and kept in
// --cache (default ~/.cache/lightlab/references) for the next run.
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli/commands.h"
#include "cli/effects_study.h"
#include "cli/scene_setup.h"
#include "cli/study_stubs.h"
#include "core/base64.h"
#include "core/error.h"
#include "core/progress.h"
#include "core/subprocess.h"
#include "core/timer.h"
#include "metrics/error_plot.h"
#include "metrics/image_metrics.h"
#include "modules/registry.h"
#include "render/render_job.h"
#include "render/technique.h"

namespace ll::cli {

namespace fs = std::filesystem;

namespace {

struct StudyOptions {
  std::string scene, knob, out, reference, referenceTechnique;
  std::vector<std::string> techniques = {"raycast"}, sets, referenceSets;
  std::string accelerator = "bvh";
  int width = 160, height = 0, spp = 1, referenceSpp = 0;  // 0: 256 when the knob is spp, else --spp
  unsigned seed = 1;
  std::string cache;      // folder of rendered references; "" = none
  bool widthGiven = false;  // --width on the command line wins over a built-in study's
};

// The built-in studies: one command each (lightlab study NAME --out DIR).
struct BuiltinStudy {
  const char* name;
  const char* what;
  const char* scene;  // under data/scenes
  const char* knob;
  std::vector<std::string> techniques, sets, referenceSets;
  const char* referenceTechnique;
  int width, spp, referenceSpp;
};

const std::vector<BuiltinStudy>& builtinStudies() {
  static const std::vector<BuiltinStudy> studies = {
      {"raycast-spp", "ray casting: samples per pixel (anti-aliasing and soft shadows)", "cornell_box.json",
       "spp=1,4,16,64", {"raycast"}, {"intersection=framework", "light_samples=4"}, {}, "", 128, 1, 256},
      {"raycast-light-samples", "ray casting: shadow rays per area light", "cornell_box.json",
       "light_samples=1,4,16,64", {"raycast"}, {"intersection=framework"}, {"light_samples=1024"}, "", 128, 1, 1},
      {"whitted-depth", "Whitted: recursion depth", "whitted_1980.json", "max_depth=0,1,2,3,4,6",
       {"whitted"}, {}, {"max_depth=16"}, "", 160, 1, 1},
      {"radiosity-patch-size", "radiosity: patch size (meshing, form factors and solve)", "cornell_box.json",
       "patch_size=0.3,0.2,0.12,0.08", {"radiosity"}, {"hemicube_res=16"}, {"patch_size=0.05"}, "", 96, 1, 1},
      {"radiosity-form-factors", "radiosity: form-factor method", "cornell_box.json",
       "form_factors=hemicube,analytic,montecarlo", {"radiosity"}, {"patch_size=0.12"},
       {"form_factors=analytic", "visibility_samples=16"}, "", 96, 1, 1},
      {"radiosity-hierarchical",
       "hierarchical radiosity (Hanrahan et al. 1991): link threshold, against path-traced ground truth",
       "cornell_box.json", "link_epsilon=1e-3,1e-4,1e-5,1e-6", {"radiosity"}, {"solver=hierarchical"}, {}, "path",
       64, 1, 4096},
      {"radiosity-iterations", "radiosity: Jacobi iterations (the Neumann series, term by term)", "cornell_box.json",
       "max_iterations=1,2,4,8,16,32", {"radiosity"}, {"patch_size=0.12", "solver=jacobi", "tolerance=1e-9"},
       {"max_iterations=1000"}, "", 96, 1, 1},
      {"raster-shading", "rasterizer: shading frequency against the ray-cast image", "bunny.json",
       "shading=flat,gouraud,phong", {"blinn-phong"}, {"samples=4"}, {"intersection=framework"}, "raycast", 160, 1,
       4},
      {"raster-samples", "rasterizer: supersampling", "cornell_box.json", "samples=1,4,16", {"blinn-phong"}, {},
       {"samples=16"}, "", 128, 1, 4},
      {"accel", "accelerators: build + trace time (all exact, so the error is 0)", "cornell_bunny.json",
       "accel=none,bvh,kdtree,octree", {"raycast"}, {"intersection=framework", "light_samples=4"}, {}, "", 96, 1, 1},
      {"bvh-split", "BVH split method: build + trace time (exact, so the error is 0)",
       "cornell_bunny.json", "split=median,equal-counts,sah", {"raycast"},
       {"intersection=framework", "light_samples=4"}, {}, "", 96, 1, 1},
      {"path-spp", "path tracing: samples per pixel (the error falls as 1/spp)", "cornell_box.json",
       "spp=1,4,16,64,256", {"path"}, {}, {}, "", 64, 1, 4096},
      {"path-strategies",
       "path tracing: light, BSDF and MIS sampling on copper and aluminium at three roughnesses: one image, "
       "different noise",
       "metal_spheres.json", "spp=4,16,64,256", {"path:strategy=light", "path:strategy=bsdf", "path:strategy=mis"},
       {}, {"strategy=mis"}, "path", 96, 1, 4096},
      {"spectral",
       "path tracing the measured Cornell box spectrally (hero wavelengths) against RGB: what spectra change, "
       "what they cost",
       "cornell_box_spectral.json", "spp=4,16,64,256", {"path:spectral=true", "path:spectral=false"}, {},
       {"spectral=true"}, "path", 64, 1, 4096},
      {"ground-truth",
       "ray casting, Whitted and radiosity against path-traced ground truth: what each misses, what it saves",
       "cornell_box.json", "spp=1,4,16,64", {"raycast", "whitted", "radiosity", "path"},
       {"intersection=framework", "patch_size=0.08", "hemicube_res=16"},
       {}, "path", 64, 1, 4096},
  };
  return studies;
}

struct Run {
  std::string technique, value, image;
  double buildSeconds = 0.0, renderSeconds = 0.0;
  uint64_t rays = 0;
  ImageError error;
};

// A curve is a technique, or a technique with parameters of its own: "path:strategy=light" (several
// joined by ';'), so one study can compare settings of one technique side by side.
struct Curve {
  std::string technique;
  std::vector<std::string> sets;
};
Curve parseCurve(const std::string& spec) {
  Curve c{spec.substr(0, spec.find(':')), {}};
  if (spec.find(':') == std::string::npos) return c;
  std::stringstream list(spec.substr(spec.find(':') + 1));
  for (std::string a; std::getline(list, a, ';');)
    if (!a.empty()) c.sets.push_back(a);
  return c;
}

// One render: the study's settings with `changes` (name=value; "spp" and "accel" are ours). The stubs it
// ran go into `stubs`.
Image render(const StudyOptions& o, const std::string& curve, const std::vector<std::string>& changes, Run* run,
             StudyStubs& stubs) {
  const Curve parsed = parseCurve(curve);
  const std::string& technique = parsed.technique;
  std::string accel = o.accelerator;
  int spp = o.spp;
  std::vector<std::string> extra;  // the knob's or the reference's changes: must fit this technique
  for (const std::string& c : changes) {
    const std::string name = c.substr(0, c.find('=')), value = c.substr(c.find('=') + 1);
    if (name == "accel") {
      accel = value;
    } else if (name == "spp") {
      try {
        spp = std::stoi(value);
      } catch (const std::exception&) {
        spp = 0;
      }
      if (spp < 1 || spp > 1 << 20) throwUserError("study: spp=" + value + " is not a sample count (1..1048576)");
    } else {
      extra.push_back(c);
    }
  }
  // A --set applies where it is declared (this technique or the accelerator): with several techniques,
  // one's parameter is no error for another (each --set is checked once, up front).
  std::vector<std::string> sets;
  const ParamSet tp("technique", findTechnique(technique).params);
  const ParamSet ap("accelerator", findAccelerator(accel).params);
  for (const std::string& a : o.sets) {
    const std::string name = a.substr(0, a.find('='));
    if (tp.has(name) || ap.has(name)) sets.push_back(a);
  }
  sets.insert(sets.end(), parsed.sets.begin(), parsed.sets.end());
  sets.insert(sets.end(), extra.begin(), extra.end());
  SceneSetup s = setUpScene(o.scene, technique, accel, sets);
  RenderSettings settings;
  settings.width = o.width;
  settings.height = o.height > 0 ? o.height : std::max(1, o.width * s.scene.camera.height / s.scene.camera.width);
  settings.spp = spp;
  settings.seed = o.seed;
  const auto t = s.technique->make();
  RenderJob job(s.scene, *s.accel, *t, s.techniqueParams, settings);
  const Timer timer;
  job.run();
  stubs.add(job.stats().missingTasks);
  if (run) {
    run->buildSeconds = s.buildSeconds;
    run->renderSeconds = timer.seconds();
    run->rays = job.stats().work.totalRays();
  }
  return job.frame().resolve(false);
}

// Letters, digits, '.', '-' kept; anything else becomes '_'.
std::string fileSafe(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-') c = '_';
  return s;
}

// A PNG file the study wrote, as a data URI for the self-contained page.
std::string pngDataUri(const fs::path& png) { return "data:image/png;base64," + base64(readTextFile(png.string())); }

// Where references are cached by default: $XDG_CACHE_HOME/lightlab/references,
// else ~/.cache/lightlab/references ("" without either).
std::string defaultReferenceCache() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return (fs::path(xdg) / "lightlab" / "references").string();
  if (const char* home = std::getenv("HOME"); home && *home)
    return (fs::path(home) / ".cache" / "lightlab" / "references").string();
  return "";
}

// 64-bit FNV-1a.
uint64_t fnv1a(const std::string& text, uint64_t h = 14695981039346656037ull) {
  for (const unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  return h;
}

// The cache file of a rendered reference: named by a hash of everything the
// image depends on -- the scene file's bytes, the technique, every parameter
// change, size, seed -- and of this build of lightlab (its size and time), so
// a rebuilt renderer never reuses a stale ground truth.
std::string cachedReferencePath(const StudyOptions& o, const std::string& technique,
                                const std::vector<std::string>& changes) {
  std::string key = readTextFile(o.scene) + "\n" + technique + "\n";
  for (const std::string& c : o.sets) key += "set " + c + "\n";
  for (const std::string& c : changes) key += "change " + c + "\n";
  key += std::to_string(o.width) + "x" + std::to_string(o.height) + " seed " + std::to_string(o.seed) + "\n";
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    key += std::to_string(fs::file_size(exe, ec)) + " ";
    key += std::to_string(fs::last_write_time(exe, ec).time_since_epoch().count());
  }
  char name[64];
  std::snprintf(name, sizeof(name), "%016llx.pfm", static_cast<unsigned long long>(fnv1a(key)));
  return (fs::path(o.cache) / name).string();
}

}  // namespace

Command addStudyCommand(CLI::App& app, const GlobalOptions& global) {
  auto o = std::make_shared<StudyOptions>();
  CLI::App* cmd = app.add_subcommand("study", "Accuracy against time: sweep a knob, time each render, plot its error");
  std::string builtinHelp;
  for (const BuiltinStudy& b : builtinStudies()) builtinHelp += std::string("\n  ") + b.name + ": " + b.what;
  builtinHelp += "\n  effects: the effects each scene calls for, measured, and every technique's error against "
                 "path-traced ground truth against its time (--scenes, --tolerance)";
  auto effects = std::make_shared<EffectsStudyOptions>();
  cmd->add_option("--scenes", effects->scenes, "study effects: the scenes (default: eight bundled ones)")
      ->delimiter(',');
  cmd->add_option("--tolerance", effects->tolerance, "study effects: the relMSE a technique may be off by")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("scene", o->scene, "Scene file (.json or .obj), or a built-in study:" + builtinHelp)->required();
  auto effectsScenes = std::make_shared<std::vector<std::string>>();
  cmd->add_option("effects_scenes", *effectsScenes, "study effects SCENE...: the scenes to study (as --scenes)");
  cmd->add_option("--knob", o->knob, "NAME=v1,v2,...: a technique or accelerator parameter, spp, or accel");
  cmd->add_option("-t,--technique", o->techniques,
                  "Technique(s), comma separated: one curve each; TECHNIQUE:name=value;... gives a curve "
                  "its own parameters (path:strategy=light)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("-a,--accel", o->accelerator, "Accelerator")->capture_default_str();
  cmd->add_option("--set", o->sets, "Parameter of every render, name=value (repeatable)");
  CLI::Option* width =
      cmd->add_option("--width", o->width, "Image width in pixels")->capture_default_str()->check(CLI::Range(1, 8192));
  cmd->add_option("--height", o->height, "Image height (default: the camera's aspect)")->check(CLI::Range(0, 8192));
  cmd->add_option("--spp", o->spp, "Samples per pixel (unless the knob is spp)")->capture_default_str()->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--seed", o->seed, "Seed of the random streams")->capture_default_str();
  cmd->add_option("--reference", o->reference, "Reference image (.pfm/.hdr/.png) instead of rendering one");
  cmd->add_option("--reference-technique", o->referenceTechnique, "Technique of the rendered reference (default: the first)");
  cmd->add_option("--reference-spp", o->referenceSpp,
                  "Samples per pixel of the rendered reference (default: 256 if the knob is spp, else --spp)")
      ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--reference-set", o->referenceSets, "Parameter change of the rendered reference, name=value");
  cmd->add_option("--out", o->out, "Output folder: study.csv, study.html, images (default: out/STUDY)");
  o->cache = defaultReferenceCache();
  cmd->add_option("--cache", o->cache,
                  "Folder where rendered references are kept and reused (\"\" = none; default: " + o->cache + ")");
  return [o, width, effects, effectsScenes, &global]() {
    o->widthGiven = width->count() > 0;
    if (o->out.empty()) o->out = (fs::path("out") / fs::path(o->scene).stem()).string();
    if (o->scene != "effects" && !effectsScenes->empty())
      throwUserError("study: one scene or built-in study at a time (got '" + o->scene + "' and '" +
                     effectsScenes->front() + "'); several scenes are for `study effects SCENE...`");
    if (o->scene == "effects") {
      effects->scenes.insert(effects->scenes.end(), effectsScenes->begin(), effectsScenes->end());
      effects->out = o->out;
      if (o->widthGiven) effects->width = o->width;
      if (o->referenceSpp > 0) effects->referenceSpp = o->referenceSpp;
      return runEffectsStudy(*effects, global.quiet);
    }
    setPrecomputationCache(false);  // each render's time includes its own precomputation (radiosity's solve)
    for (const BuiltinStudy& b : builtinStudies()) {
      if (o->scene != b.name) continue;
      o->scene = std::string(LIGHTLAB_SOURCE_DIR) + "/data/scenes/" + b.scene;
      if (o->knob.empty()) o->knob = b.knob;
      o->techniques = b.techniques;
      o->sets.insert(o->sets.begin(), b.sets.begin(), b.sets.end());
      if (o->referenceSets.empty()) o->referenceSets = b.referenceSets;
      if (o->referenceTechnique.empty()) o->referenceTechnique = b.referenceTechnique;
      if (!o->widthGiven) o->width = b.width;
      o->spp = b.spp;
      if (o->referenceSpp == 0) o->referenceSpp = b.referenceSpp;
    }
    if (o->knob.empty()) throwUserError("study: --knob NAME=v1,v2,... is needed (unless SCENE names a built-in study)");
    const auto eq = o->knob.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == o->knob.size())
      throwUserError("study: --knob must be NAME=v1,v2,... (got '" + o->knob + "')");
    const std::string knob = o->knob.substr(0, eq);
    std::vector<std::string> values;
    std::stringstream list(o->knob.substr(eq + 1));
    for (std::string v; std::getline(list, v, ',');)
      if (!v.empty()) values.push_back(v);
    if (values.empty()) throwUserError("study: --knob " + knob + "= lists no values");
    // The knob must exist for every technique (or the accelerator) before anything renders.
    for (const std::string& a : o->sets) {  // every --set is some technique's or the accelerator's
      const std::string name = a.substr(0, a.find('='));
      bool known = ParamSet("accelerator", findAccelerator(o->accelerator).params).has(name);
      for (const std::string& t : o->techniques)
        known = known || ParamSet("t", findTechnique(parseCurve(t).technique).params).has(name);
      if (!known) {
        const std::string first = parseCurve(o->techniques.front()).technique;
        ParamSet("technique '" + first + "'", findTechnique(first).params).assign(a);
      }
    }
    for (const std::string& t : o->techniques) {  // a curve's own parameters are its technique's
      const Curve c = parseCurve(t);
      ParamSet tp("technique '" + c.technique + "'", findTechnique(c.technique).params);
      for (const std::string& a : c.sets) tp.assign(a);
    }
    if (knob != "spp" && knob != "accel")
      for (const std::string& t : o->techniques) {
        const std::string name = parseCurve(t).technique;
        ParamSet tp("technique '" + name + "'", findTechnique(name).params);
        const ParamSet ap("accelerator '" + o->accelerator + "'", findAccelerator(o->accelerator).params);
        if (!tp.has(knob) && !ap.has(knob)) tp.assign(knob + "=" + values.front());  // throws, naming the parameters
      }
    std::error_code ec;
    fs::create_directories(fs::path(o->out) / "images", ec);
    if (ec) throwUserError("study: cannot create " + o->out + ": " + ec.message());

    // The reference.
    StudyStubs stubs;
    Image reference;
    if (!o->reference.empty()) {
      reference = loadImage(o->reference);
    } else {
      std::vector<std::string> changes = o->referenceSets;
      const int spp = o->referenceSpp > 0 ? o->referenceSpp : knob == "spp" ? 256 : o->spp;
      changes.push_back("spp=" + std::to_string(spp));
      const std::string technique = o->referenceTechnique.empty() ? o->techniques.front() : o->referenceTechnique;
      const std::string cached = o->cache.empty() ? "" : cachedReferencePath(*o, technique, changes);
      std::error_code exists;
      if (!cached.empty() && fs::exists(cached, exists)) {
        reference = loadImage(cached);
        if (!global.quiet) std::fprintf(stderr, "study: reference from the cache %s\n", cached.c_str());
      } else {
        reference = render(*o, technique, changes, nullptr, stubs);
        if (!global.quiet) std::fprintf(stderr, "study: reference rendered (%s, %d spp)\n", technique.c_str(), spp);
        if (!cached.empty()) {
          std::error_code ignored;  // a cache that cannot be written only costs time next run
          fs::create_directories(fs::path(cached).parent_path(), ignored);
          if (!ignored) saveImage(reference, cached);
        }
      }
      saveImage(reference, (fs::path(o->out) / "reference.pfm").string());
    }

    std::vector<Run> runs;
    ProgressBar progress("study " + knob, static_cast<double>(values.size() * o->techniques.size()), global.quiet);
    for (const std::string& technique : o->techniques)
      for (const std::string& v : values) {
        Run run;
        run.technique = technique;
        run.value = v;
        const Image image = render(*o, technique, {knob + "=" + v}, &run, stubs);
        if (image.width() != reference.width() || image.height() != reference.height())
          throwUserError("study: the reference is " + std::to_string(reference.width()) + "x" +
                         std::to_string(reference.height()) + ", the renders " + std::to_string(image.width()) + "x" +
                         std::to_string(image.height()) + " (set --width/--height)");
        run.error = compareImages(image, reference);
        run.image = "images/" + fileSafe(technique + "_" + knob + "_" + v) + ".png";
        saveImage(image, (fs::path(o->out) / run.image).string());
        runs.push_back(run);
        progress.update(static_cast<double>(runs.size()));
      }
    progress.finish();

    // study.csv
    const std::string csvPath = (fs::path(o->out) / "study.csv").string();
    std::ofstream csv(csvPath);
    if (!csv) throwUserError("study: cannot write " + csvPath);
    csv << "technique," << knob << ",seconds,build_seconds,render_seconds,rays,rmse,relmse,ssim,image\n";
    for (const Run& r : runs)
      csv << r.technique << "," << r.value << "," << r.buildSeconds + r.renderSeconds << "," << r.buildSeconds << ","
          << r.renderSeconds << "," << r.rays << "," << r.error.rmse << "," << r.error.relmse << "," << r.error.ssim
          << "," << r.image << "\n";
    csv.close();

    // study.html: the plot and the images, all inline.
    std::vector<PlotSeries> series;
    for (const std::string& technique : o->techniques) {
      PlotSeries s{technique, {}};
      for (const Run& r : runs)
        if (r.technique == technique)
          s.points.push_back({r.buildSeconds + r.renderSeconds, r.error.relmse, knob + "=" + r.value});
      series.push_back(s);
    }
    const std::string title = fs::path(o->scene).filename().string() + ": relMSE against time, knob " + knob;
    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html lang='en'><head><meta charset='utf-8'><title>" << title
         << "</title><style>body{font:15px/1.4 sans-serif;margin:24px;background:#f6f6f4}table{border-collapse:"
            "collapse;background:#fff}td,th{padding:3px 10px;border-bottom:1px solid #ddd;text-align:right}"
            "figure{display:inline-block;margin:6px}img{image-rendering:pixelated;width:200px}figcaption{font-size:"
            "12px;text-align:center}</style></head><body>\n<h1>"
         << title << "</h1>\n"
         << stubs.html()
         << logLogSvg(series, title, "seconds (accelerator build + render)", "relMSE against the reference")
         << "<table><tr><th>technique</th><th>" << knob
         << "</th><th>seconds</th><th>build</th><th>render</th><th>rays</th><th>relMSE</th><th>RMSE</th><th>SSIM</th></tr>\n";
    for (const Run& r : runs) {
      char row[512];
      std::snprintf(row, sizeof(row),
                    "<tr><td>%s</td><td>%s</td><td>%.4g</td><td>%.4g</td><td>%.4g</td><td>%llu</td><td>%.3g</td>"
                    "<td>%.3g</td><td>%.4f</td></tr>\n",
                    r.technique.c_str(), r.value.c_str(), r.buildSeconds + r.renderSeconds, r.buildSeconds,
                    r.renderSeconds, static_cast<unsigned long long>(r.rays), r.error.relmse, r.error.rmse,
                    r.error.ssim);
      html << row;
    }
    const fs::path referencePng = fs::path(o->out) / "images" / "reference.png";
    saveImage(reference, referencePng.string());
    html << "</table>\n<h2>Images</h2>\n<figure><img src='" << pngDataUri(referencePng)
         << "'><figcaption>reference</figcaption></figure>\n";
    for (const Run& r : runs)
      html << "<figure><img src='" << pngDataUri(fs::path(o->out) / r.image) << "'><figcaption>"
           << r.technique << " " << knob << "=" << r.value << "</figcaption></figure>\n";
    html << "</body></html>\n";
    const std::string htmlPath = (fs::path(o->out) / "study.html").string();
    std::ofstream page(htmlPath);
    if (!page) throwUserError("study: cannot write " + htmlPath);
    page << html.str();
    for (const Run& r : runs)
      std::printf("%-12s %s=%-8s %9.4f s  relMSE %.3g  SSIM %.4f\n", r.technique.c_str(), knob.c_str(), r.value.c_str(),
                  r.buildSeconds + r.renderSeconds, r.error.relmse, r.error.ssim);
    std::printf("wrote %s and %s\n", csvPath.c_str(), htmlPath.c_str());
    stubs.print();
  };
}

}  // namespace ll::cli
