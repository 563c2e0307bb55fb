// Frame rate of the software rasterizer `blinn-phong` (assignment 1): one
// frame = one renderPass at 640x480 after prepare() (mesh and mipmaps built
// once per scene, as a GPU upload would be). The target: the 59k
// bunny with Phong shading at >= 30 frames per second on 2 cores.
//   build/tests/bench/lightlab_bench --benchmark_filter=Raster
#include <benchmark/benchmark.h>

#include <atomic>
#include <string>

#include <tbb/global_control.h>

#include "modules/registry.h"
#include "render/frame_buffer.h"
#include "render/render_stats.h"
#include "render/student_task.h"
#include "render/technique.h"
#include "scene/scene_loader.h"

namespace {

using namespace ll;

// Arguments: threads, supersamples per pixel (1, 4, 16).
void rasterFrames(benchmark::State& state, const std::string& scenePath, const char* shading) {
  const auto threads = static_cast<size_t>(state.range(0));
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const Scene scene = loadScene(scenePath);
  const AcceleratorInfo& accelInfo = findAccelerator("none");
  const ParamSet accelParams("accelerator 'none'", accelInfo.params);
  const auto accel = buildAccelerator(accelInfo, accelParams, scene.geometry);
  const TechniqueInfo& info = findTechnique("blinn-phong");
  ParamSet params("technique 'blinn-phong'", info.params);
  params.set("shading", shading);
  params.set("samples", std::to_string(state.range(1)));
  RenderSettings settings;
  settings.width = 640;
  settings.height = 480;
  TaskLog log;
  const RenderContext ctx{scene, *accel, params, settings, &log};
  auto technique = info.make();
  technique->prepare(ctx);
  FrameBuffer fb(settings.width, settings.height);
  const std::atomic<bool> cancel{false};
  for (auto _ : state) {
    fb.clear();
    WorkCounters counters;
    technique->renderPass(ctx, 0, fb, counters, cancel);
    benchmark::DoNotOptimize(counters.nonFinite);
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["threads"] = static_cast<double>(threads);
  state.counters["triangles"] = static_cast<double>(scene.geometry.triangleCount());
}

void BM_RasterBunny59kPhong(benchmark::State& state) {
  rasterFrames(state, std::string(LIGHTLAB_BUILD_DATA_DIR) + "/scenes/bunny_59k.json", "phong");
}
void BM_RasterBunny59kGouraud(benchmark::State& state) {
  rasterFrames(state, std::string(LIGHTLAB_BUILD_DATA_DIR) + "/scenes/bunny_59k.json", "gouraud");
}
void BM_RasterTexturedFloorPhong(benchmark::State& state) {
  rasterFrames(state, std::string(LIGHTLAB_DATA_DIR) + "/scenes/textured_floor.json", "phong");
}

BENCHMARK(BM_RasterBunny59kPhong)
    ->ArgsProduct({{1, 2}, {1, 4, 16}})
    ->ArgNames({"threads", "samples"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_RasterBunny59kGouraud)
    ->Args({2, 1})
    ->ArgNames({"threads", "samples"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_RasterTexturedFloorPhong)
    ->Args({2, 1})
    ->Args({2, 16})
    ->ArgNames({"threads", "samples"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
