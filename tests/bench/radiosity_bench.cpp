// Radiosity on the Cornell box (assignment 5): meshing, form factors and the
// solve, each phase timed, at about 6,000 patches. The target: form
// factors plus solution within 5 s on 2 cores.
//   build/tests/bench/lightlab_bench --benchmark_filter=Radiosity
#include <benchmark/benchmark.h>

#include <chrono>
#include <string>

#include <tbb/global_control.h>

#include "modules/registry.h"
#include "radiosity_scene.h"
#include "render/render_job.h"
#include "scene/scene_loader.h"

namespace {

using namespace ll;

// Arguments: hemicube resolution, solver (0 gauss-seidel, 1 southwell, 2 jacobi).
void BM_RadiosityCornell(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/cornell_box.json");
  a5::RadiositySettings r;
  r.patchSize = 0.05f;
  r.formFactors.hemicubeResolution = static_cast<int>(state.range(0));
  r.solver.method = state.range(1) == 1   ? a5::SolverMethod::Southwell
                    : state.range(1) == 2 ? a5::SolverMethod::Jacobi
                                          : a5::SolverMethod::GaussSeidel;
  double mesh = 0, ff = 0, solve = 0, patches = 0, nonZeros = 0;
  for (auto _ : state) {
    const auto s = a5::solveSceneUncached(scene, r);
    mesh += s->patches->meshSeconds + s->patches->accelSeconds;
    ff += s->patches->formFactorSeconds;
    solve += s->solution.seconds;
    patches = static_cast<double>(s->mesh().patches.size());
    nonZeros = static_cast<double>(s->f().column.size());
  }
  const auto n = static_cast<double>(state.iterations());
  state.counters["patches"] = patches;
  state.counters["nonzeros"] = nonZeros;
  state.counters["mesh_s"] = mesh / n;
  state.counters["formfactors_s"] = ff / n;
  state.counters["solve_s"] = solve / n;
}

BENCHMARK(BM_RadiosityCornell)
    ->Args({16, 0})
    ->Args({32, 0})
    ->Args({32, 1})
    ->Args({32, 2})
    ->ArgNames({"hemicube", "solver"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace

namespace {

// Progressive refinement (-t radiosity --set progressive=true) on the same
// Cornell box: the time from a fresh scene to the first displayed picture
// (mesh, accelerator, 32 shots with their hemicube rows, one 512x512 pass).
// The target: within 0.2 s.
void BM_RadiosityProgressiveFirstImage(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
  const TechniqueInfo& info = findTechnique("radiosity");
  const AcceleratorInfo& none = findAccelerator("none");
  ParamSet params(info.name, info.params);
  params.set("progressive", "true");
  params.set("patch_size", "0.05");
  RenderSettings settings;
  settings.spp = 8;  // passes: shots 32, 64, ..., the last to the tolerance
  for (auto _ : state) {
    // A scene the caches have never seen: a fresh load with the light nudged per iteration.
    Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/cornell_box.json");
    for (Material& m : scene.materials)
      if (m.emits()) m.emission *= 1.0f + 1e-3f * static_cast<float>(state.iterations());
    const auto accel = buildAccelerator(none, ParamSet(none.name, none.params), scene.geometry);
    auto technique = info.make();
    RenderJob job(scene, *accel, *technique, params, settings);
    const auto start = std::chrono::steady_clock::now();
    double first = 0.0;
    job.run([&](int pass, int) {
      if (pass == 1) first = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    });
    state.SetIterationTime(first);
    state.counters["all_passes_s"] = job.stats().renderSeconds + job.stats().prepareSeconds;
  }
}

BENCHMARK(BM_RadiosityProgressiveFirstImage)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(3);

}  // namespace
