#include "radiosity_scene.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <list>
#include <mutex>

#include "core/progress.h"
#include "render/student_task.h"
#include "render/technique.h"

namespace ll {
// The accelerators the patches can be traced with (assignment 4 and the framework).
AcceleratorInfo bvhAccelerator();
AcceleratorInfo kdtreeAccelerator();
AcceleratorInfo octreeAccelerator();
AcceleratorInfo bruteForceAccelerator();
#ifdef LIGHTLAB_HAVE_EMBREE
AcceleratorInfo embreeAccelerator();  // framework/accel/embree_accelerator.cpp
#endif
}  // namespace ll

namespace ll::a5 {

namespace {

AcceleratorInfo acceleratorNamed(const std::string& name) {
#ifdef LIGHTLAB_HAVE_EMBREE
  if (name == "embree") return embreeAccelerator();
#endif
  return name == "kdtree" ? kdtreeAccelerator()
         : name == "octree" ? octreeAccelerator()
         : name == "none"   ? bruteForceAccelerator()
                            : bvhAccelerator();
}

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// FNV-1a over the scene's geometry and materials: a reloaded or edited scene
// gets a new key even at a freed scene's address.
uint64_t fingerprint(const Scene& s) {
  uint64_t h = 1469598103934665603ull;
  const auto mix = [&](const void* data, size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t k = 0; k < bytes; ++k) h = (h ^ p[k]) * 1099511628211ull;
  };
  mix(s.geometry.positions.data(), s.geometry.positions.size() * sizeof(Vec3));
  mix(s.geometry.triangles.data(), s.geometry.triangles.size() * sizeof(glm::uvec3));
  mix(s.geometry.spheres.data(), s.geometry.spheres.size() * sizeof(Sphere));
  for (const Material& m : s.materials) {
    mix(&m.kd, sizeof m.kd);
    mix(&m.emission, sizeof m.emission);
  }
  for (const SceneObject& o : s.objects) mix(&o.material, sizeof o.material);
  return h;
}

std::string patchKey(const Scene& s, const RadiositySettings& r) {
  const FormFactorSettings& f = r.formFactors;
  return std::to_string(fingerprint(s)) + "|" + std::to_string(r.patchSize) + "|" + std::to_string(r.sphereSegments) +
         "|" + r.accelerator + "|" + methodName(f.method) + "|" + std::to_string(f.hemicubeResolution) + "|" +
         std::to_string(f.visibilitySamples) + "|" + std::to_string(f.monteCarloSamples) + "|" +
         std::to_string(r.adaptivePasses) + "|" + std::to_string(r.adaptiveThreshold);
}

std::string solveKey(const std::string& patches, const RadiositySettings& r) {
  const SolverSettings& v = r.solver;
  return patches + "|" + methodName(v.method) + "|" + std::to_string(v.tolerance) + "|" +
         std::to_string(v.maxIterations) + "|" + std::to_string(static_cast<int>(r.show)) + "|" + std::to_string(r.bounce);
}

std::shared_ptr<const PatchScene> computePatches(const Scene& scene, const RadiositySettings& r,
                                                 bool formFactors = true) {
  auto out = std::make_shared<PatchScene>();
  TaskLog log;  // catches the A5.1 stub
  const ScopedTaskLog scope(&log);
  auto t = std::chrono::steady_clock::now();
  reportPhase("patch mesh");
  out->mesh = buildPatchMesh(scene, r.patchSize * scene.geometry.sceneBounds().diagonal(), r.sphereSegments);
  out->meshSeconds = since(t);
  out->refinement.push_back(out->mesh.patches.size());
  const AcceleratorInfo info = acceleratorNamed(r.accelerator);
  const auto buildAccel = [&] {
    reportPhase("patch accelerator (" + info.name + ")");
    t = std::chrono::steady_clock::now();
    out->accel = info.make(ParamSet(info.name, info.params));
    out->accel->build(out->mesh.geometry);
    out->accelSeconds += since(t);
  };
  buildAccel();
  for (int round = 0; round < r.adaptivePasses && formFactors; ++round) {
    // Solve this mesh, then split where neighbouring patches (sharing a corner) differ too much.
    // Each round reports as it goes (a bar on the terminal, the phase in a pane), so a pane's newer
    // request cancels it: the report throws.
    const std::string phase =
        "adaptive round " + std::to_string(round + 1) + " of " + std::to_string(r.adaptivePasses);
    FormFactors f;
    {
      ProgressBar bar(phase + ": form factors (" + std::to_string(out->mesh.patches.size()) + " patches)",
                      static_cast<double>(out->mesh.patches.size()), r.quiet);
      f = computeFormFactors(out->mesh, *out->accel, r.formFactors, nullptr,
                             [&](size_t done, size_t) { bar.update(static_cast<double>(done)); });
    }
    const RadiositySystem system{out->mesh.patches, f};
    SolverSettings quick = r.solver;
    quick.method = SolverMethod::GaussSeidel;
    const std::vector<Rgb> b =
        solveRadiosity(system, quick, [&](const SolverStep&) { reportPhase(phase + ": solve"); }).radiosity;
    std::vector<uint8_t> split(b.size(), 0);
    size_t marked = 0;
    for (uint32_t i = 0; i < b.size(); ++i)
      for (int k = 0; k < 3; ++k)
        for (const uint32_t j : out->mesh.vertexPatches[out->mesh.patches[i].vertices[k]]) {
          const float brighter = std::max(maxComponent(b[i]), maxComponent(b[j]));
          if (!split[i] && brighter > 0.0f && maxComponent(glm::abs(b[i] - b[j])) > r.adaptiveThreshold * brighter) {
            split[i] = 1;
            ++marked;
          }
        }
    if (marked == 0) break;
    t = std::chrono::steady_clock::now();
    out->mesh = refinePatchMesh(scene, out->mesh, split);
    out->meshSeconds += since(t);
    out->refinement.push_back(out->mesh.patches.size());
    buildAccel();
  }
  if (!formFactors) return out;
  t = std::chrono::steady_clock::now();
  {
    ProgressBar bar("form factors (" + methodName(r.formFactors.method) + ", " +
                        std::to_string(out->mesh.patches.size()) + " patches)",
                    static_cast<double>(out->mesh.patches.size()), r.quiet);
    out->f = computeFormFactors(out->mesh, *out->accel, r.formFactors, &out->diagnostics,
                                [&](size_t done, size_t) { bar.update(static_cast<double>(done)); });
  }
  out->formFactorSeconds = since(t);
  out->missingTasks = log.missing();
  out->tasksRan = log.ran();
  return out;
}

std::shared_ptr<const SolvedRadiosity> computeSolution(std::shared_ptr<const PatchScene> patches,
                                                       const RadiositySettings& r) {
  auto out = std::make_shared<SolvedRadiosity>();
  out->patches = std::move(patches);
  TaskLog log;  // catches the A5.2 / A5.3 stubs
  const ScopedTaskLog scope(&log);
  const RadiositySystem system = out->system();
  {
    ProgressBar bar("radiosity (" + methodName(r.solver.method) + ")", 1.0, r.quiet);
    double first = -1.0;
    out->solution = solveRadiosity(system, r.solver, [&](const SolverStep& s) {
      // Progress: the residual's way down to the tolerance, on a log scale.
      if (first < 0.0) first = s.residual;
      if (s.residual > 0.0 && first > r.solver.tolerance && r.solver.tolerance > 0.0)
        bar.update(std::clamp(std::log(first / s.residual) / std::log(first / r.solver.tolerance), 0.0, 1.0));
    });
  }
  if (!out->solution.failure.empty())  // once per solve (solves are cached), quiet or not: the picture is wrong
    std::fprintf(stderr, "lightlab: radiosity (%s, %zu patches) NOT converged: %s\n", methodName(r.solver.method).c_str(),
                 out->mesh().patches.size(), out->solution.failure.c_str());
  const PatchMesh& mesh = out->mesh();
  const std::vector<Rgb>& b = out->solution.radiosity;
  switch (r.show) {
    case RadiositySettings::Show::Solution:
      out->shown = b;
      for (size_t i = 0; i < b.size(); ++i) out->shown[i] += mesh.patches[i].reflectance * out->solution.ambient;
      break;
    case RadiositySettings::Show::Bounce:
      out->shown = bounce(system, r.bounce);
      break;
    case RadiositySettings::Show::Bounces: {
      out->shown.assign(b.size(), Rgb(0.0f));
      for (int k = 0; k <= r.bounce; ++k) {
        const std::vector<Rgb> term = bounce(system, k);
        for (size_t i = 0; i < term.size(); ++i) out->shown[i] += term[i];
      }
      break;
    }
  }
  for (Rgb& shown : out->shown)
    if (!isFinite(shown)) shown = Rgb(0.0f);  // (bounces of a system with non-finite input; the failure says so)
  out->vertexShown.assign(mesh.positions.size(), Rgb(0.0f));
  for (size_t v = 0; v < out->vertexShown.size(); ++v) {
    float area = 0.0f;
    for (uint32_t p : mesh.vertexPatches[v]) {
      out->vertexShown[v] += out->shown[p] * mesh.patches[p].area;
      area += mesh.patches[p].area;
    }
    if (area > 0.0f) out->vertexShown[v] /= area;
  }
  out->energy = energyBalance(system, b);
  out->missingTasks = out->patches->missingTasks;
  for (const auto& [id, what] : log.missing()) out->missingTasks[id] = what;
  out->tasksRan = out->patches->tasksRan;
  for (const auto& [id, byReference] : log.ran()) out->tasksRan[id] = byReference;
  return out;
}


}  // namespace

RadiositySettings radiositySettings(const ParamSet& p) {
  RadiositySettings r;
  r.patchSize = static_cast<float>(p.getFloat("patch_size"));
  r.sphereSegments = p.getInt("sphere_segments");
  r.accelerator = p.getChoice("patch_accelerator");
  const std::string& ff = p.getChoice("form_factors");
  r.formFactors.method = ff == "analytic" ? FormFactorMethod::Analytic
                         : ff == "montecarlo" ? FormFactorMethod::MonteCarlo
                                              : FormFactorMethod::Hemicube;
  r.formFactors.hemicubeResolution = p.getInt("hemicube_res");
  r.formFactors.visibilitySamples = p.getInt("visibility_samples");
  r.formFactors.monteCarloSamples = p.getInt("mc_samples");
  const std::string& solver = p.getChoice("solver");
  r.solver.method = solver == "direct"         ? SolverMethod::Direct
                    : solver == "jacobi"       ? SolverMethod::Jacobi
                    : solver == "southwell"    ? SolverMethod::Southwell
                                               : SolverMethod::GaussSeidel;
  r.solver.tolerance = p.getFloat("tolerance");
  r.solver.maxIterations = p.getInt("max_iterations");
  const std::string& show = p.getChoice("show");
  r.show = show == "bounce" ? RadiositySettings::Show::Bounce
           : show == "bounces" ? RadiositySettings::Show::Bounces
                               : RadiositySettings::Show::Solution;
  r.bounce = p.getInt("bounce");
  r.progressive = p.getBool("progressive");
  r.adaptivePasses = p.getInt("adaptive_passes");
  r.adaptiveThreshold = static_cast<float>(p.getFloat("adaptive_threshold"));
  return r;
}

ProgressiveScene progressiveScene(const Scene& scene, const RadiositySettings& settings) {
  if (!precomputationCacheEnabled()) {
    ProgressiveScene s;
    s.patches = computePatches(scene, settings, false);
    s.state = std::make_shared<ProgressiveRadiosity>(s.patches->mesh, *s.patches->accel,
                                                     settings.formFactors.hemicubeResolution);
    return s;
  }
  static std::mutex mutex;
  static std::list<std::pair<std::string, ProgressiveScene>> cache;  // newest first
  const std::string k = std::to_string(fingerprint(scene)) + "|" + std::to_string(settings.patchSize) + "|" +
                        std::to_string(settings.sphereSegments) + "|" + settings.accelerator + "|" +
                        std::to_string(settings.formFactors.hemicubeResolution);
  const std::lock_guard lock(mutex);
  for (auto it = cache.begin(); it != cache.end(); ++it)
    if (it->first == k) {
      cache.splice(cache.begin(), cache, it);
      return cache.front().second;
    }
  ProgressiveScene s;
  s.patches = computePatches(scene, settings, false);
  s.state = std::make_shared<ProgressiveRadiosity>(s.patches->mesh, *s.patches->accel,
                                                   settings.formFactors.hemicubeResolution);
  cache.emplace_front(k, s);
  if (cache.size() > 2) cache.pop_back();
  return s;
}

std::shared_ptr<const SolvedRadiosity> solveSceneUncached(const Scene& scene, const RadiositySettings& settings) {
  return computeSolution(computePatches(scene, settings), settings);
}

std::shared_ptr<const SolvedRadiosity> solveScene(const Scene& scene, const RadiositySettings& settings) {
  if (!precomputationCacheEnabled()) return solveSceneUncached(scene, settings);
  static std::mutex mutex;
  // Newest first; a few of each, so switching between panes' settings does not recompute.
  static std::list<std::pair<std::string, std::shared_ptr<const PatchScene>>> patchCache;
  static std::list<std::pair<std::string, std::shared_ptr<const SolvedRadiosity>>> solveCache;
  const std::string pk = patchKey(scene, settings), sk = solveKey(pk, settings);
  const std::lock_guard lock(mutex);  // (one solve at a time: it uses every core already)
  const auto find = [](auto& cache, const std::string& k) {
    for (auto it = cache.begin(); it != cache.end(); ++it)
      if (it->first == k) {
        cache.splice(cache.begin(), cache, it);
        return cache.front().second;
      }
    return typename std::decay_t<decltype(cache.front().second)>{};
  };
  if (auto solved = find(solveCache, sk)) return solved;
  auto patches = find(patchCache, pk);
  if (!patches) {
    patches = computePatches(scene, settings);
    patchCache.emplace_front(pk, patches);
    if (patchCache.size() > 3) patchCache.pop_back();
  }
  auto solved = computeSolution(patches, settings);
  solveCache.emplace_front(sk, solved);
  if (solveCache.size() > 8) solveCache.pop_back();
  return solved;
}

void SolvedRadiosity::replayTasks() const {
  for (const auto& [id, what] : missingTasks) reportMissingTask(id.c_str(), what.c_str());
  if (TaskLog* log = currentTaskLog())
    for (const auto& [id, byReference] : tasksRan) log->noteRan(id, byReference);
}

}  // namespace ll::a5
