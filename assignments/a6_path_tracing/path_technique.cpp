// Technique `path` -- unidirectional Monte Carlo path tracing, the
// rendering equation's estimate and LightLab's ground truth:
//
//   lightlab render SCENE -t path --spp 256 [--set max_depth=16] [--set rr_depth=3]
//                   [--set strategy=mis|light|bsdf]
//
// At every vertex: the emission the path found (weighted by MIS against
// light sampling), one light sample by next-event estimation (A6.2), then a
// direction from the BSDF (cosine-weighted for the diffuse lobe, A6.1;
// visible GGX normals for rough metals and rough glass, A6.4), and
// after rr_depth bounces Russian roulette (A6.3). Strategies: `mis` combines
// light and BSDF sampling by the power heuristic; `light` takes direct light
// only from light samples, `bsdf` only from paths that hit an emitter (point
// and directional lights then contribute nothing: a random direction never
// hits a point). The sky (the scene's background, a colour or an HDR image)
// is a light like the others: sampled by next-event estimation and weighted
// by MIS where a path escapes. Ambient light (ka Ia) is a local-model device and is not
// used. Framework code: students write the functions in a6_tasks.h.
//
// Light-path classes (render/light_path_class.h): every contribution is
// added to the class of its path (emission, direct-lighting, ..., caustics)
// when the frame buffer keeps them; they sum to the picture. With
// `--set effects=measured` a short probe (render/light_path_probe.h) first
// measures each class, and the classes whose absence changes the picture by
// less than `effects_tolerance` (relMSE, the probe's 95 % upper bound) are
// left out: their contributions are not added, their shadow rays not traced,
// and a path ends as soon as no class it could still reach is kept.
#include <algorithm>
#include <memory>
#include <optional>

#include "a6_tasks.h"
#include "bsdf.h"
#include "light_sampler.h"
#include "spectral.h"
#include "render/light_path_probe.h"
#include "render/media.h"
#include "render/ray_offset.h"
#include "render/technique.h"
#include "core/timer.h"
#include "render/render_job.h"
#include "scene/camera.h"

namespace ll {

TechniqueInfo pathTechnique();

namespace {

enum class Strategy { Mis, Light, Bsdf };

class PathTracing final : public PixelTechnique {
 public:
  explicit PathTracing(LightPathMask keep = kAllLightPathClasses) : fixedKeep_(keep) {}
  bool splitsLightPaths() const override { return true; }
  std::optional<SkippedWork> skippedWork() const override { return skipped_; }

  void prepare(const RenderContext& ctx) override {
    camera_ = renderCamera(ctx.scene, ctx.settings);
    frame_.emplace(camera_);
    lights_.emplace(ctx.scene);
    maxDepth_ = ctx.params.getInt("max_depth");
    rrDepth_ = ctx.params.getInt("rr_depth");
    const std::string strategy = ctx.params.getChoice("strategy");
    strategy_ = strategy == "light" ? Strategy::Light : strategy == "bsdf" ? Strategy::Bsdf : Strategy::Mis;
    if (ctx.params.getBool("spectral")) {
      if (!spectral_) spectral_.emplace();
    } else {
      spectral_.reset();
    }
    keep_ = fixedKeep_;
    skipped_.reset();
    if (ctx.params.getChoice("effects") == "measured") measureEffects(ctx);
  }

 protected:
  Rgb renderSample(const RenderContext& ctx, const PixelSample& s, const Tracer& tracer) const override {
    const Scene& scene = ctx.scene;
    Rng& rng = *s.rng;
    Ray ray = referenceCameraRay(camera_, *frame_, s.position.x, s.position.y);
    ray.dir = glm::normalize(ray.dir);
    RayKind kind = RayKind::Camera;
    Rgb radiance(0.0f), throughput(1.0f);
    Media media;
    // Spectral: the three wavelengths this path carries in its channels (spectral.h).
    const a6::Wavelengths wl = spectral_ ? a6::Wavelengths::sample(rng.uniform()) : a6::Wavelengths{};
    bool heroOnly = false;  // a dispersive refraction left only the hero wavelength
    const auto colour = [&](const Rgb& rgb) { return spectral_ ? spectral_->upsample(rgb, wl) : rgb; };
    const auto mediumIor = [&](const Media& md) {
      const Material* inside = md.innermost(scene);
      return inside && spectral_ ? inside->iorAt(wl.nm[0]) : md.ior(scene);
    };
    const auto dispersive = [&](const Media& md) {
      const Material* inside = md.innermost(scene);
      return inside && inside->dispersive();
    };
    const auto mediumAbsorption = [&](const Media& md) {
      return md.count == 0 ? Rgb(0.0f) : colour(md.absorption(scene));
    };
    bool deltaBounce = true;  // the last direction had no density (camera ray, mirror, glass): no MIS
    float bsdfPdf = 0.0f;     // the density of the last smooth bounce, for MIS at an emitter it hits
    LightPathState path;      // the events so far, for the class of what the path finds
    const auto add = [&](const Rgb& contribution, LightPathClass c) {  // a contribution of class c, if kept
      if (!(keep_ & lightPathBit(c))) return;
      radiance += contribution;
      if (s.lightPaths) s.lightPaths[static_cast<size_t>(c)] += contribution;
    };
    for (int bounce = 0;; ++bounce) {
      Hit hit;
      if (!tracer.intersect(ray, hit, kind)) {  // the sky, weighted by MIS against its light samples
        float weight = 1.0f;
        if (!deltaBounce && lights_->hasSky()) {
          if (strategy_ == Strategy::Light) weight = 0.0f;
          if (strategy_ == Strategy::Mis) weight = a6::powerHeuristic(bsdfPdf, lights_->pdfSky(ray.dir));
        }
        // A backdrop (lights_scene false) is seen, directly or through mirrors and glass, but lights nothing.
        if (scene.environment.lightsScene() || path.atLight(true) != LightPathClass::SkyLight)
          add(throughput * colour(scene.environment.radiance(ray.dir)) * weight, path.atLight(true));
        break;
      }
      const Rgb sigma = mediumAbsorption(media);  // Beer-Lambert along the segment just travelled
      if (!isBlack(sigma)) throughput *= glm::exp(-sigma * hit.t);
      const SurfacePoint sp = scene.surfacePoint(ray, hit);
      const Material& sceneMaterial = *sp.material;
      std::optional<Material> spectralMaterial;
      if (spectral_) spectralMaterial = spectral_->materialAt(sceneMaterial, sp.uv, wl);
      const Material& m = spectral_ ? *spectralMaterial : sceneMaterial;
      a6::ShadingPoint x;
      x.position = sp.position;
      x.wo = -ray.dir;
      const bool front = glm::dot(sp.geometricNormal, x.wo) > 0.0f;
      x.ng = faceTowards(sp.geometricNormal, x.wo);
      x.n = faceTowards(sp.shadingNormal, x.wo);

      if (front && m.emits()) {  // emitters emit on their front side
        float weight = 1.0f;
        if (!deltaBounce) {
          if (strategy_ == Strategy::Light) weight = 0.0f;  // light sampling already counted it
          if (strategy_ == Strategy::Mis)
            weight = a6::powerHeuristic(bsdfPdf, lights_->pdfSolidAngle(hit.prim, hit.t, glm::dot(x.ng, x.wo)));
        }
        add(throughput * m.emission * weight, path.atLight());
      }
      if (bounce >= maxDepth_) break;

      // The media on both sides, for a dielectric.
      const auto id = static_cast<uint32_t>(&sceneMaterial - scene.materials.data());
      const Media behind = !m.transmits() ? media : front ? media.with(id) : media.without(id);
      const float n1 = mediumIor(media), n2 = m.transmits() ? (front ? m.ior : mediumIor(behind)) : n1;
      const a6::Bsdf bsdf(m, spectral_ ? m.kd : m.diffuse(sp.uv), x, n1, n2);

      // This surface's event when it scatters through a smooth lobe: G for a rough microfacet surface.
      const PathVertex smooth = m.glossyScattering() ? PathVertex::Glossy : PathVertex::Diffuse;
      const LightPathState litHere = path.then(smooth);
      // The light sample's random numbers are drawn even when its class is left out: the other classes
      // then see the same random streams as a full render.
      if (bsdf.hasSmoothLobes() && strategy_ != Strategy::Bsdf && !lights_->empty()) {
        a6::LightSample light = lights_->sample(rng.uniform(), rng.uniform2(), x.position);
        if (keep_ & lightPathBit(litHere.atLight(light.sky))) {
          if (spectral_)
            light.emission = spectral_->at(light.material ? light.material->emissionSpectrum.get() : nullptr,
                                           light.emission, wl);
          add(throughput * a6::nextEventEstimate(x, light, bsdf, tracer, strategy_ == Strategy::Mis),
              litHere.atLight(light.sky));
        }
      }
      const float uLobe = rng.uniform();
      const Vec2 u = rng.uniform2();
      const std::optional<a6::BsdfSample> next = bsdf.sample(x.wo, u, uLobe);
      if (!next) break;
      path = path.then(!next->delta          ? smooth
                       : next->transmitted ? PathVertex::SpecularRefraction
                                           : PathVertex::SpecularReflection);
      if (!(path.reachable() & keep_)) break;  // nothing kept lies further along this path
      // With light sampling only, a last smooth bounce could add nothing: no ray for it.
      if (!next->delta && strategy_ == Strategy::Light && bounce + 1 >= maxDepth_) break;
      throughput *= next->weight;
      // A dispersive interface sends each wavelength its own way: only the hero goes on (Wilkie et al. 2014).
      if (spectral_ && !heroOnly && m.transmits() && (sceneMaterial.dispersive() || dispersive(media))) {
        throughput = Rgb(3.0f * throughput.r, 0.0f, 0.0f);
        heroOnly = true;
      }
      // No light sample covers a delta direction or one through the surface (A6.2 lights only the front):
      // an emitter found there counts in full.
      deltaBounce = next->delta || next->transmitted;
      bsdfPdf = next->pdf;
      if (next->transmitted) media = behind;
      if (bounce + 1 >= rrDepth_ && !a6::russianRoulette(throughput, rng.uniform())) break;
      if (isBlack(throughput)) break;
      ray = Ray{};
      ray.origin = offsetRayOrigin(x.position, faceTowards(x.ng, next->wi));
      ray.dir = next->wi;
      kind = !next->delta ? RayKind::Indirect : next->transmitted ? RayKind::Refraction : RayKind::Reflection;
    }
    if (spectral_ && s.lightPaths)
      for (size_t c = 0; c < kLightPathClassCount; ++c) s.lightPaths[c] = spectral_->toRgb(s.lightPaths[c], wl);
    return spectral_ ? spectral_->toRgb(radiance, wl) : radiance;
  }

 private:
  // --set effects=measured: a probe at the same parameters measures each class; the classes whose absence
  // stays within effects_tolerance (relMSE, 95 % upper bound) are left out, fewest-first by their error.
  void measureEffects(const RenderContext& ctx) {
    const Timer timer;
    ParamSet probeParams = ctx.params;
    probeParams.set("effects", "all");
    LightPathProbeSettings ps;
    // The seed `lightlab info` probes with (whatever the render's --seed): both make the same call on a scene.
    const LightPathProbe probe(ctx.scene, ctx.accel, pathTechnique(), probeParams, ps);
    const double tolerance = ctx.params.getFloat("effects_tolerance");
    std::vector<std::pair<double, LightPathClass>> order;
    for (int c = 0; c < kLightPathClassCount; ++c)
      order.emplace_back(probe.relMseWithout(lightPathBit(lightPathClassAt(c))).high, lightPathClassAt(c));
    std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    LightPathMask skip = 0;
    for (const auto& [error, c] : order)
      if (probe.relMseWithout(skip | lightPathBit(c)).high <= tolerance) skip |= lightPathBit(c);
    // Only the classes the scene produces at all are worth naming.
    LightPathMask present = 0;
    for (int c = 0; c < kLightPathClassCount; ++c)
      if (probe.share(lightPathClassAt(c)).high > 0.0) present |= lightPathBit(lightPathClassAt(c));
    keep_ = fixedKeep_ & ~skip;
    SkippedWork w;
    w.tolerance = tolerance;
    w.leftOut = skip;
    const Estimate added = probe.relMseWithout(skip);
    w.errorAdded = added.value;
    w.errorAddedHigh = added.high;
    std::string names;
    for (int c = 0; c < kLightPathClassCount; ++c)
      if (skip & present & lightPathBit(lightPathClassAt(c)))
        names += std::string(names.empty() ? "" : ", ") + lightPathClassName(lightPathClassAt(c));
    w.skipped = names.empty() ? "nothing: every class the scene has shows" : names;
    // The saving, measured where something the scene has is left out: the probe's first batches again,
    // skipping, against the same batches in full (timed now, next to it, so the machine's load is alike).
    if (skip & present) {
      const auto timePerPass = [&](LightPathMask keep) {
        PathTracing technique(keep);
        RenderSettings rs;
        rs.width = probe.width();
        rs.height = probe.height();
        rs.spp = ps.sppPerBatch * ps.minBatches;
        rs.seed = ps.seed;
        RenderJob job(ctx.scene, ctx.accel, technique, probeParams, rs);
        job.run();
        return job.stats().renderSeconds / rs.spp;
      };
      w.secondsPerPassFull = timePerPass(fixedKeep_);
      w.secondsPerPassSkipping = timePerPass(keep_);
    }
    w.probeSeconds = timer.seconds();
    skipped_ = w;
  }

  LightPathMask fixedKeep_ = kAllLightPathClasses;  // the classes this instance may add
  LightPathMask keep_ = kAllLightPathClasses;       // ... after effects=measured left some out
  std::optional<SkippedWork> skipped_;
  std::optional<a6::SpectralContext> spectral_;
  Camera camera_;
  std::optional<CameraFrame> frame_;
  std::optional<a6::LightSampler> lights_;
  int maxDepth_ = 16, rrDepth_ = 3;
  Strategy strategy_ = Strategy::Mis;
};

}  // namespace

TechniqueInfo pathTechnique() {
  return {
      "path",
      "Monte Carlo path tracing of the rendering equation: next-event estimation and BSDF sampling combined by "
      "MIS, Russian roulette, every material and light; the ground truth the other techniques are measured against",
      EffectSet{Effect::DirectLighting, Effect::HardShadows, Effect::SoftShadows, Effect::MirrorReflection,
                Effect::Refraction, Effect::GlossyHighlights, Effect::DiffuseInterreflection, Effect::Textures,
                Effect::Emission, Effect::GlossyReflection, Effect::SkyLight, Effect::Dispersion, Effect::Caustics},
      10,
      withEffectsParams(
          {
              ParamDecl::integer("max_depth", 16, 0, 256,
                                 "most bounces of a path (0 = what the camera sees emitted, 1 = direct light only)"),
              ParamDecl::integer("rr_depth", 3, 0, 256, "bounces before Russian roulette may end a path"),
              ParamDecl::boolean("spectral", false,
                                 "hero-wavelength spectral rendering: measured spectra, RGB upsampled (Smits 1999), "
                                 "dispersion; false = RGB"),
              ParamDecl::choice("strategy", "mis", {"mis", "light", "bsdf"},
                                "direct light from: mis = light and BSDF sampling combined; "
                                "light = light samples only; bsdf = only paths that hit an emitter"),
          },
          "a short path-traced probe first, then leave out the light-path classes whose absence stays within "
          "effects_tolerance (the probe's 95 % upper bound)"),
      []() -> std::unique_ptr<Technique> { return std::make_unique<PathTracing>(); },
      false,
      {{"spectral", "true", EffectSet{Effect::Dispersion}}},  // one index per material in RGB
  };
}

}  // namespace ll
