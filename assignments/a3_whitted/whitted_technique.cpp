// Technique `whitted` -- recursive ray tracing (Whitted 1980): at every hit
// the lecture's local Blinn-Phong term with shadow rays, plus the mirror-
// reflected and the refracted radiance, traced recursively (A3.4's
// radiance()). Dielectrics split by the Fresnel equations (or Schlick's
// approximation), with total internal reflection, Beer-Lambert absorption
// and nested media; the recursion stops at a depth and a weight.
//
//   lightlab render SCENE -t whitted [--set max_depth=5] [--set min_throughput=0.001]
//     [--set fresnel=exact|schlick] [--set shadows=filtered|opaque] [--set light_samples=16]
//   lightlab trace SCENE --pixel X Y -t whitted --json   # the ray tree of one pixel
//
// Rays are spawned only where the scene calls for them: a reflection ray
// only off a mirror or a dielectric, a refraction ray only into a
// dielectric, shadow rays only when something can cast a shadow.
#include <cmath>
#include <memory>
#include <optional>

#include "render/technique.h"
#include "scene/camera.h"
#include "whitted_tracer.h"

namespace ll {

namespace {

class Whitted final : public PixelTechnique {
 public:
  void prepare(const RenderContext& ctx) override {
    camera_ = renderCamera(ctx.scene, ctx.settings);
    frame_.emplace(camera_);
    const ParamSet& p = ctx.params;
    settings_.maxDepth = p.getInt("max_depth");
    settings_.minThroughput = static_cast<float>(p.getFloat("min_throughput"));
    settings_.schlick = p.getChoice("fresnel") == "schlick";
    settings_.filteredShadows = p.getChoice("shadows") == "filtered";
    settings_.lightSamples = p.getInt("light_samples");
  }

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
      []() -> std::unique_ptr<Technique> { return std::make_unique<Whitted>(); },
  };
}

}  // namespace ll
