// Technique `whitted` -- recursive ray tracing (Whitted 1980): at every hit
// the lecture's local Blinn-Phong term with shadow rays, plus the mirror-
// reflected and the refracted radiance, traced recursively (A3.4's
// radiance()). Dielectrics split by the Fresnel equations (or Schlick's
// approximation), with total internal reflection, Beer-Lambert absorption
// and nested media; the recursion stops at a depth and a weight.
//
//   lightlab render SCENE -t whitted [--set max_depth=5] [--set min_throughput=0.001]
//     [--set fresnel=exact|schlick] [--set shadows=filtered|opaque] [--set light_samples=16]
//     [--set effects=measured [--set effects_tolerance=0.001]]
//   lightlab trace SCENE --pixel X Y -t whitted --json   # the ray tree of one pixel
//
// Rays are spawned only where the scene calls for them: a reflection ray
// only off a mirror or a dielectric, a refraction ray only into a
// dielectric, shadow rays only when something can cast a shadow; with
// effects=measured, not even those whose light does not show (measured).
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/timer.h"
#include "metrics/image_metrics.h"
#include "render/light_path_probe.h"
#include "render/render_job.h"
#include "render/technique.h"
#include "scene/camera.h"
#include "whitted_tracer.h"

namespace ll {

namespace {

class Whitted final : public PixelTechnique {
 public:
  Whitted() = default;
  // A Whitted tracer that leaves these classes out whatever its parameters say (effects=measured's trials).
  explicit Whitted(LightPathMask leftOut) : fixedLeftOut_(leftOut) {}

  void prepare(const RenderContext& ctx) override {
    camera_ = renderCamera(ctx.scene, ctx.settings);
    frame_.emplace(camera_);
    const ParamSet& p = ctx.params;
    settings_.maxDepth = p.getInt("max_depth");
    settings_.minThroughput = static_cast<float>(p.getFloat("min_throughput"));
    settings_.schlick = p.getChoice("fresnel") == "schlick";
    settings_.filteredShadows = p.getChoice("shadows") == "filtered";
    settings_.lightSamples = p.getInt("light_samples");
    skipped_.reset();
    const LightPathMask leftOut = fixedLeftOut_            ? *fixedLeftOut_
                                  : p.getChoice("effects") == "measured" ? measureEffects(ctx)
                                                                         : 0;
    settings_.skipRefraction = leftOut & lightPathBit(LightPathClass::Refraction);
    settings_.skipMirrorReflection = leftOut & lightPathBit(LightPathClass::MirrorReflection);
  }

  std::optional<SkippedWork> skippedWork() const override { return skipped_; }

  std::optional<RayTree> rayTree(const RenderContext& ctx, Vec2 position) const override {
    WorkCounters counters;
    const Tracer tracer(ctx.scene, ctx.accel, counters);
    // The random stream of the pixel's first sample, as the render draws it.
    const auto pixel = static_cast<uint64_t>(std::floor(position.y)) * static_cast<uint64_t>(camera_.width) +
                       static_cast<uint64_t>(std::floor(position.x));
    Rng rng = Rng::forPixel(ctx.settings.seed, pixel, 0);
    RayTree tree;
    const a3::WhittedTracer whitted(ctx.scene, tracer, settings_, rng, &tree);
    whitted.traceCamera(referenceCameraRay(camera_, *frame_, position.x, position.y));
    return tree;
  }

 protected:
  Rgb renderSample(const RenderContext& ctx, const PixelSample& s, const Tracer& tracer) const override {
    const a3::WhittedTracer whitted(ctx.scene, tracer, settings_, *s.rng);
    return whitted.traceCamera(referenceCameraRay(camera_, *frame_, s.position.x, s.position.y));
  }

 private:
  // --set effects=measured. Whitted's picture is cheap, so it measures itself rather than asking the path
  // tracer's probe: small renders (the probe's 128 px width, 4 passes, the render's own seed) with and
  // without each class it could leave out -- refraction rays, then reflection rays -- and the classes whose
  // absence changes that picture by at most effects_tolerance (relMSE), fewest-first, are left out.
  LightPathMask measureEffects(const RenderContext& ctx) {
    const Timer timer;
    RenderSettings rs = ctx.settings;
    rs.width = std::min(camera_.width, LightPathProbeSettings{}.width);
    rs.height = std::max(1, rs.width * camera_.height / camera_.width);
    rs.spp = 4;
    rs.lightPaths = false;
    const auto render = [&](LightPathMask leftOut) {
      Whitted trial(leftOut);
      RenderJob job(ctx.scene, ctx.accel, trial, ctx.params, rs);
      job.run();
      return std::make_pair(job.frame().resolve(false), job.stats().renderSeconds / rs.spp);
    };
    const auto [full, fullSeconds] = render(0);
    // Only the classes whose rays the scene spawns at all are candidates: each one's error and time alone.
    struct Candidate {
      double error, secondsPerPass;
      LightPathClass cls;
    };
    std::vector<Candidate> candidates;
    for (const auto& [cls, spawned] : {std::pair{LightPathClass::Refraction, ctx.scene.hasTransmission},
                                       std::pair{LightPathClass::MirrorReflection, ctx.scene.hasMirrors}})
      if (spawned) {
        const auto [without, perPass] = render(lightPathBit(cls));
        candidates.push_back({compareImages(without, full).relmse, perPass, cls});
      }
    std::sort(candidates.begin(), candidates.end(),
              [](const Candidate& a, const Candidate& b) { return a.error < b.error; });
    const double tolerance = ctx.params.getFloat("effects_tolerance");
    LightPathMask leftOut = 0;
    double error = 0.0, seconds = fullSeconds;
    for (const Candidate& c : candidates) {
      if (c.error > tolerance) break;
      double together = c.error, perPass = c.secondsPerPass;  // the first one left out: its own render
      if (leftOut) {
        const auto [without, combinedPerPass] = render(leftOut | lightPathBit(c.cls));
        together = compareImages(without, full).relmse;
        perPass = combinedPerPass;
      }
      if (together > tolerance) break;
      leftOut |= lightPathBit(c.cls);
      error = together;
      seconds = perPass;
    }
    SkippedWork w;
    w.tolerance = tolerance;
    w.leftOut = leftOut;
    w.errorAdded = error;
    w.errorAddedHigh = error;  // measured on the same streams: no sampling interval
    std::string names;
    for (const Candidate& c : candidates)
      if (leftOut & lightPathBit(c.cls)) names += std::string(names.empty() ? "" : ", ") + lightPathClassName(c.cls);
    w.skipped = candidates.empty() ? "nothing: the scene has no mirror or glass to skip"
                : names.empty()     ? "nothing: the light of its reflection and refraction rays shows"
                                    : names + " (their rays not traced)";
    if (leftOut) {
      w.secondsPerPassFull = fullSeconds;
      w.secondsPerPassSkipping = seconds;
    }
    w.probeSeconds = timer.seconds();
    skipped_ = w;
    return leftOut;
  }

  std::optional<LightPathMask> fixedLeftOut_;  // set in measureEffects()'s trial renders: they measure nothing
  std::optional<SkippedWork> skipped_;
  Camera camera_;
  std::optional<CameraFrame> frame_;
  a3::WhittedSettings settings_;
};

}  // namespace

TechniqueInfo whittedTechnique() {
  return {
      "whitted",
      "recursive ray tracing (Whitted 1980): local Blinn-Phong with shadow rays, mirror reflection, refraction "
      "with Fresnel, total internal reflection, absorption and nested dielectrics",
      EffectSet{Effect::DirectLighting, Effect::HardShadows, Effect::SoftShadows, Effect::MirrorReflection,
                Effect::Refraction, Effect::GlossyHighlights, Effect::Textures, Effect::Emission},
      2,
      withEffectsParams(
          {
            ParamDecl::integer("max_depth", 5, 0, 64, "deepest ray traced (0 = camera rays only, as ray casting)"),
            ParamDecl::real("min_throughput", 1e-3, 0.0, 1.0,
                            "rays weighing less than this in the pixel (max over r, g, b) are not traced"),
            ParamDecl::choice("fresnel", "exact", {"exact", "schlick"},
                              "exact: the Fresnel equations for unpolarised light; schlick: Schlick's approximation"),
            ParamDecl::choice("shadows", "filtered", {"filtered", "opaque"},
                              "filtered: shadow rays pass through transmissive surfaces, tinted by them and absorbed "
                              "inside (Beer-Lambert); opaque: "
                              "every surface blocks light"),
            ParamDecl::integer("light_samples", 16, 1, 1024, "shadow-ray samples per area light per pixel sample"),
          },
          "leave out refraction or mirror-reflection rays whose light changes the picture by less than "
          "effects_tolerance (measured on a small render with and without them)"),
      []() -> std::unique_ptr<Technique> { return std::make_unique<Whitted>(); },
  };
}

}  // namespace ll
