#include "render/technique.h"

#include <array>
#include <atomic>
#include <cmath>
#include <mutex>

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>

#include "core/phase_progress.h"
#include "render/student_task.h"

namespace ll {

EffectSet TechniqueInfo::simulatesWith(const ParamSet& values) const {
  EffectSet s = simulates;
  for (const ParamEffect& e : onlyWith) {
    std::string value;
    if (values.has(e.param)) {
      value = values.text(e.param);
    } else {
      for (const ParamDecl& d : params)
        if (d.name == e.param) value = d.defaultValue;
    }
    if (value != e.value) s = s.minus(e.effects);
  }
  return s;
}

EffectSet TechniqueInfo::simulatesIn(const Scene& scene, const ParamSet& values) const {
  const EffectSet s = simulatesWith(values);
  if (!ignoresLightsOf(scene)) return s;
  return s.minus(EffectSet{Effect::DirectLighting, Effect::HardShadows, Effect::DiffuseInterreflection,
                           Effect::GlossyHighlights, Effect::Caustics});
}

const char* TechniqueInfo::lightsNote(const Scene& scene) const {
  return ignoresLightsOf(scene) ? " (its light comes from emissive surfaces only, not point lights)" : "";
}

namespace {
std::atomic<bool> precomputationCache{true};
}  // namespace

bool precomputationCacheEnabled() { return precomputationCache.load(); }
void setPrecomputationCache(bool enabled) { precomputationCache = enabled; }

Vec2 stratifiedOffset(int index, int count, Rng& rng) {
  return count <= 1 ? Vec2(0.5f) : stratifiedSample(index, count, rng);
}

Vec2 stratifiedSample(int index, int count, Rng& rng) {
  const Vec2 jitter = rng.uniform2();
  if (count <= 1) return jitter;
  const int n = static_cast<int>(std::lround(std::sqrt(static_cast<double>(count))));
  if (n * n == count) {  // an n x n grid, one jittered sample per cell
    const int cell = index % count;
    return (Vec2(static_cast<float>(cell % n), static_cast<float>(cell / n)) + jitter) / static_cast<float>(n);
  }
  // Otherwise `count` columns, one sample anywhere in each: the strata must tile the pixel, or the
  // estimate is biased (8 of the 9 cells of a 3 x 3 grid leave a ninth of the pixel unsampled).
  const int column = index % count;
  return Vec2((static_cast<float>(column) + jitter.x) / static_cast<float>(count), jitter.y);
}

void PixelTechnique::renderPass(const RenderContext& ctx, int pass, FrameBuffer& fb, WorkCounters& counters,
                                const std::atomic<bool>& cancel) {
  constexpr int kTile = 16;
  beginPass(ctx, pass, fb);
  if (cancel.load(std::memory_order_relaxed)) return;
  const int spp = samplesPerPixel(ctx);
  const int w = fb.width(), h = fb.height();
  std::mutex merge;
  // The pass's progress, in twentieths of its tiles, for the phase sink (the GUI pane's caption).
  const PhaseSink* sink = currentPhaseSink();
  const int tiles = ((w + kTile - 1) / kTile) * ((h + kTile - 1) / kTile);
  std::atomic<int> tilesDone{0};
  tbb::parallel_for(
      tbb::blocked_range2d<int>(0, h, kTile, 0, w, kTile),
      [&](const tbb::blocked_range2d<int>& tile) {
        if (cancel.load(std::memory_order_relaxed)) return;
        const ScopedTaskLog scopedLog(ctx.taskLog);
        WorkCounters local;
        const Tracer tracer(ctx.scene, accelerator(ctx), local);
        for (int y = tile.rows().begin(); y < tile.rows().end(); ++y)
          for (int x = tile.cols().begin(); x < tile.cols().end(); ++x) {
            const uint64_t pixel = static_cast<uint64_t>(y) * static_cast<uint64_t>(w) + static_cast<uint64_t>(x);
            Rng rng = Rng::forPixel(ctx.settings.seed, pixel, static_cast<uint64_t>(pass));
            PixelSample s;
            s.x = x;
            s.y = y;
            s.pass = pass;
            s.rng = &rng;
            s.position = Vec2(static_cast<float>(x), static_cast<float>(y)) + stratifiedOffset(pass, spp, rng);
            std::array<Rgb, kLightPathClassCount> classes;
            if (fb.keepsLightPaths()) {
              classes.fill(Rgb(0.0f));
              s.lightPaths = classes.data();
            }
            takeStubFlag();
            Rgb value = renderSample(ctx, s, tracer);
            if (!isFinite(value)) {
              ++local.nonFinite;
              value = Rgb(0.0f);
              classes.fill(Rgb(0.0f));
            }
            fb.add(x, y, value);
            if (s.lightPaths) fb.addLightPaths(x, y, pass, classes.data());
            if (takeStubFlag()) fb.markStub(x, y);
          }
        {
          std::lock_guard lock(merge);
          counters.add(local);
        }
        const int done = ++tilesDone;
        if (sink && *sink && (done * 20) / tiles != ((done - 1) * 20) / tiles)
          (*sink)("pass", static_cast<double>(done) / tiles);
      },
      tbb::simple_partitioner());
}

}  // namespace ll
