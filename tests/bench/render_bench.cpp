// Whole-frame render benchmarks: what `lightlab render SCENE -t raycast` costs
// at 512x512, per accelerator / intersection mode and thread count; and the
// Whitted 1980 scene with `-t whitted`.
#include <benchmark/benchmark.h>

#include <tbb/global_control.h>

#include "modules/registry.h"
#include "render/render_job.h"
#include "scene/scene_loader.h"

namespace {

using namespace ll;

void renderScene(benchmark::State& state, const char* scene, const char* intersection, int spp,
                 const char* techniqueName = "raycast", const char* accelName = "none", int width = 512,
                 int height = 512) {
  const auto threads = static_cast<size_t>(state.range(0));
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const Scene s = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/" + scene);
  const AcceleratorInfo& info = findAccelerator(accelName);
  const ParamSet accelParams(info.name, info.params);
  const auto accel = buildAccelerator(info, accelParams, s.geometry);
  const TechniqueInfo& t = findTechnique(techniqueName);
  ParamSet params(t.name, t.params);
  if (intersection) params.set("intersection", intersection);
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.spp = spp;
  uint64_t rays = 0;
  for (auto _ : state) {
    auto technique = t.make();
    RenderJob job(s, *accel, *technique, params, settings);
    job.run();
    rays += job.stats().work.totalRays();
    benchmark::DoNotOptimize(job.frame().passes());
  }
  state.counters["Mrays/s"] = benchmark::Counter(static_cast<double>(rays) * 1e-6, benchmark::Counter::kIsRate);
  state.counters["threads"] = static_cast<double>(threads);
}

void BM_CornellRaycastStudent(benchmark::State& state) { renderScene(state, "cornell_box.json", "student", 1); }
void BM_CornellRaycastFramework(benchmark::State& state) { renderScene(state, "cornell_box.json", "framework", 1); }
void BM_WhittedRaycastFramework(benchmark::State& state) { renderScene(state, "whitted_1980.json", "framework", 1); }
// Whitted's own picture at its own size (640x480, 1 sample, recursion depth 5) with the BVH: compare with the
// lecture's VAX 11/780 (74 min), PC of 2006 (6 s) and GPU of 2012 (1/30 s).
void BM_Whitted1980(benchmark::State& state) {
  renderScene(state, "whitted_1980.json", nullptr, 1, "whitted", "bvh", 640, 480);
}

BENCHMARK(BM_CornellRaycastStudent)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CornellRaycastFramework)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_WhittedRaycastFramework)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Whitted1980)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
