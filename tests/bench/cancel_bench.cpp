// How fast long work gives way (issue 25): a pane running radiosity on the
// 235k-triangle Cornell bunny is switched to ray casting during a phase, and
// the time until the ray-cast image is done is measured (the target is 0.5 s;
// the tests only bound it loosely, at 2 s). Phases: 0 the patch mesh, 1 the
// form factors, 2 a KD-tree build (ray casting with -a kdtree).
//   build/tests/bench/lightlab_bench --benchmark_filter=SwitchAway
#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>
#include <string>
#include <thread>

#include "gui/pane_renderer.h"
#include "modules/registry.h"
#include "scene/scene_loader.h"

namespace {

using namespace ll;
using Clock = std::chrono::steady_clock;

gui::RenderRequest paneRequest(const std::shared_ptr<const Scene>& scene, const std::string& technique,
                               const std::string& accelerator = "bvh") {
  gui::RenderRequest r;
  r.scene = scene;
  r.sceneVersion = 1;
  r.technique = technique;
  r.techniqueParams = ParamSet("technique '" + technique + "'", findTechnique(technique).params);
  r.accelerator = accelerator;
  r.accelParams = ParamSet("accelerator '" + accelerator + "'", findAccelerator(accelerator).params);
  r.settings.width = 64;
  r.settings.height = 64;
  r.settings.spp = 1;
  return r;
}

void BM_SwitchAwayFromRadiosityOnTheBigBunny(benchmark::State& state) {
  static const auto scene = std::make_shared<const Scene>(
      loadScene(std::string(LIGHTLAB_BUILD_DATA_DIR) + "/scenes/cornell_bunny_235k.json"));
  const std::string phase = state.range(0) == 0 ? "patch mesh" : state.range(0) == 1 ? "form factors" : "kd-tree build";
  gui::PaneRenderer pane;
  for (auto _ : state) {
    const uint64_t id = pane.submit(state.range(0) == 2 ? paneRequest(scene, "raycast", "kdtree") : paneRequest(scene, "radiosity"));
    while (!(pane.snapshot().request == id && pane.snapshot().phaseName.rfind(phase, 0) == 0))
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    const auto switched = Clock::now();
    pane.submit(paneRequest(scene, "raycast"));
    while (!pane.finished()) std::this_thread::sleep_for(std::chrono::microseconds(200));
    state.SetIterationTime(std::chrono::duration<double>(Clock::now() - switched).count());
  }
  state.SetLabel("switched during " + phase);
}
BENCHMARK(BM_SwitchAwayFromRadiosityOnTheBigBunny)->Arg(0)->Arg(1)->Arg(2)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(5);

}  // namespace
