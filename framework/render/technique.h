// The Technique interface: a rendering method. It declares its parameters and
// the effects it simulates in a TechniqueInfo, renders progressively pass by
// pass into a FrameBuffer, and counts its work.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "accel/accelerator.h"
#include "core/params.h"
#include "core/rng.h"
#include "render/frame_buffer.h"
#include "render/ray_tree.h"
#include "render/render_stats.h"
#include "render/student_task.h"
#include "render/tracer.h"
#include "scene/scene.h"

namespace ll {

struct RenderSettings {
  int width = 512;     // pixels
  int height = 512;
  int spp = 1;         // samples per pixel = passes for pixel techniques
  uint64_t seed = 0;   // random streams derive from (seed, pixel, sample)
  std::optional<Camera> camera;  // overrides the scene's camera (the GUI's view); width/height above win
  bool lightPaths = false;  // keep the estimate split by light-path class, where the technique can split it
};

// The camera a render uses: settings.camera or the scene's, at the settings' resolution.
inline Camera renderCamera(const Scene& scene, const RenderSettings& settings) {
  Camera c = settings.camera.value_or(scene.camera);
  c.width = settings.width;
  c.height = settings.height;
  return c;
}

struct RenderContext {
  const Scene& scene;
  const Accelerator& accel;
  const ParamSet& params;
  RenderSettings settings;
  TaskLog* taskLog = nullptr;  // where student stubs report; installed on every worker
};

class Technique {
 public:
  virtual ~Technique() = default;
  // Once per (scene, parameters) before the passes: precomputation goes here.
  virtual void prepare(const RenderContext& ctx) { (void)ctx; }
  // How many passes make the full image.
  virtual int passCount(const RenderContext& ctx) const { return ctx.settings.spp; }
  // Renders pass `pass` (0-based) into fb, adding work to `counters`. Must
  // return early (leaving the pass incomplete) when `cancel` becomes true.
  virtual void renderPass(const RenderContext& ctx, int pass, FrameBuffer& fb, WorkCounters& counters,
                          const std::atomic<bool>& cancel) = 0;
  // The ray tree of one sample at continuous image position `position`
  // (after prepare()), for techniques that trace recursively; nullopt otherwise.
  virtual std::optional<RayTree> rayTree(const RenderContext& ctx, Vec2 position) const {
    (void)ctx;
    (void)position;
    return std::nullopt;
  }
  // Whether renderPass() fills the frame buffer's light-path classes (FrameBuffer::enableLightPaths);
  // asked after prepare().
  virtual bool splitsLightPaths() const { return false; }
  // What the last prepare() decided to leave out (--set effects=measured), if anything.
  virtual std::optional<SkippedWork> skippedWork() const { return std::nullopt; }
};

// One pixel sample as a PixelTechnique sees it.
struct PixelSample {
  int x = 0, y = 0;  // pixel, (0,0) top-left
  int pass = 0;      // sample index within the pixel
  Vec2 position;     // continuous image position of the sample (pixel centre = x + 0.5)
  Rng* rng = nullptr;
  // When the frame buffer keeps light-path classes: kLightPathClassCount zeroed values that the
  // technique adds each contribution to, by its class; they sum to the returned radiance.
  Rgb* lightPaths = nullptr;
};

// Base for techniques that compute each pixel sample independently: renders
// each pass over 16x16 tiles in parallel (oneTBB), with stratified sample
// positions, the (seed, pixel, sample) random stream, NaN/Inf guarding and
// stub marking done here once for all of them.
class PixelTechnique : public Technique {
 public:
  void renderPass(const RenderContext& ctx, int pass, FrameBuffer& fb, WorkCounters& counters,
                  const std::atomic<bool>& cancel) final;

 protected:
  // Radiance along the sample's camera path. `tracer` counts rays.
  virtual Rgb renderSample(const RenderContext& ctx, const PixelSample& sample, const Tracer& tracer) const = 0;
  // The accelerator this technique traces with (default: the context's).
  virtual const Accelerator& accelerator(const RenderContext& ctx) const { return ctx.accel; }
  // Samples per pixel the passes stratify over (default: one per pass).
  virtual int samplesPerPixel(const RenderContext& ctx) const { return passCount(ctx); }
  // Called before each pass's samples. A technique whose passes refine the
  // whole picture (progressive radiosity) advances here and clears the
  // previous pass's samples (fb.clearSamples()); by default nothing happens.
  virtual void beginPass(const RenderContext& ctx, int pass, FrameBuffer& fb) {
    (void)ctx;
    (void)pass;
    (void)fb;
  }
};

// Sample position inside the unit pixel for sample `index` of `count`:
// the pixel centre for count 1; for a square count n^2, a jittered n x n
// grid; else `count` jittered columns (strata that tile the pixel, so the
// average is unbiased for any count).
Vec2 stratifiedOffset(int index, int count, Rng& rng);

// Sample `index` of `count` in the unit square for estimating an integral
// (points on an area light): a jittered n x n grid for count n^2, else
// `count` jittered columns, and for count 1 a uniform point -- never a fixed
// one, which would turn an area light into a point light at its centre
// (hard shadows that no number of passes softens).
Vec2 stratifiedSample(int index, int count, Rng& rng);

// Whether techniques may keep precomputed results (radiosity's solve) across
// renders of the same scene and settings, as the GUI wants; `lightlab study`
// turns it off so that every render pays for its own precomputation.
bool precomputationCacheEnabled();
void setPrecomputationCache(bool enabled);

struct TechniqueInfo {
  std::string name;
  std::string help;
  EffectSet simulates;  // effects this technique can reproduce
  int cost = 0;         // rough cost rank, for "cheapest technique that simulates all"
  std::vector<ParamDecl> params;
  std::unique_ptr<Technique> (*make)() = nullptr;
  bool gpu = false;  // renders with OpenGL on the offscreen context (gpu/offscreen_gl.h): the GUI sets it up
  // Effects in `simulates` that need a parameter's value (path's dispersion needs spectral=true).
  struct ParamEffect {
    std::string param, value;
    EffectSet effects;
  };
  std::vector<ParamEffect> onlyWith{};
  // Lights surfaces by point and directional lights too; radiosity's light comes only from emissive surfaces.
  bool pointLights = true;

  // What the technique simulates with these parameter values (the declared defaults where not set).
  EffectSet simulatesWith(const ParamSet& values) const;
  // ... on this scene: a technique that ignores point lights misses the light they bring (direct lighting,
  // hard shadows, and what bounces on from them) wherever a scene has one.
  EffectSet simulatesIn(const Scene& scene, const ParamSet& values) const;
  EffectSet simulatesIn(const Scene& scene) const { return simulatesIn(scene, ParamSet{}); }
  // Whether the scene has point or directional lights this technique ignores.
  bool ignoresLightsOf(const Scene& scene) const { return !pointLights && !scene.lights.empty(); }
  // " (its light comes from emissive surfaces only, not point lights)" where it does, else "".
  const char* lightsNote(const Scene& scene) const;
};

}  // namespace ll
