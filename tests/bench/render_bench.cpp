// Whole-frame render benchmarks: what `lightlab render SCENE -t raycast` costs
// at 512x512, per accelerator / intersection mode and thread count.
#include <benchmark/benchmark.h>

#include <tbb/global_control.h>

#include "modules/registry.h"
#include "render/render_job.h"
#include "scene/scene_loader.h"

namespace {

using namespace ll;

void renderScene(benchmark::State& state, const char* scene, const char* intersection, int spp) {
  const auto threads = static_cast<size_t>(state.range(0));
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const Scene s = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/" + scene);
  const AcceleratorInfo& info = findAccelerator("none");
  const ParamSet accelParams("accelerator 'none'", info.params);
  const auto accel = buildAccelerator(info, accelParams, s.geometry);
  const TechniqueInfo& t = findTechnique("raycast");
  ParamSet params("technique 'raycast'", t.params);
  params.set("intersection", intersection);
  RenderSettings settings;
  settings.width = 512;
  settings.height = 512;
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

BENCHMARK(BM_CornellRaycastStudent)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CornellRaycastFramework)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_WhittedRaycastFramework)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
