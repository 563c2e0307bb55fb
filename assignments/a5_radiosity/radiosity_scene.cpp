#include "radiosity_scene.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <list>
#include <mutex>
#include <tuple>

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
  return std::to_string(fingerprint(s)) + "|" + std::to_string(r.patchSize) + "|" + std::to_string(r.discontinuityMeshing) +
         std::to_string(r.quadPatches) +
         "|" + std::to_string(r.sphereSegments) +
         "|" + r.accelerator + "|" + methodName(f.method) + "|" + std::to_string(f.hemicubeResolution) + "|" +
         std::to_string(f.visibilitySamples) + "|" + std::to_string(f.monteCarloSamples) + "|" +
         std::to_string(r.adaptivePasses) + "|" + std::to_string(r.adaptiveThreshold) +
         (r.solver.method == SolverMethod::Hierarchical ? "|hierarchical " + std::to_string(r.hierarchical.linkEpsilon) : "");
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
  out->mesh = buildPatchMesh(scene, r.patchSize * scene.geometry.sceneBounds().diagonal(), r.sphereSegments,
                             r.discontinuityMeshing, r.quadPatches);
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
      for (int k = 0; k < out->mesh.patches[i].corners(); ++k)
        for (const uint32_t j : out->mesh.vertexPatches[out->mesh.patches[i].corner(k)]) {
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

// Hierarchical radiosity (hierarchical.h) from the scene's own polygons; its
// leaves become the patch mesh (corners welded by position, so they
// interpolate), solved there and then: the solution is part of the patches.
struct HierarchicalPatches {
  std::shared_ptr<const PatchScene> patches;
  Solution solution;
};
HierarchicalPatches computeHierarchical(const Scene& scene, const RadiositySettings& r) {
  const auto start = std::chrono::steady_clock::now();
  reportPhase("hierarchical radiosity: base patches");
  PatchMesh base = buildPatchMesh(scene, 1e30f, r.sphereSegments, false);
  const AcceleratorInfo info = acceleratorNamed(r.accelerator);
  std::unique_ptr<Accelerator> baseAccel = info.make(ParamSet(info.name, info.params));
  baseAccel->build(base.geometry);
  HierarchicalResult h;
  {
    ProgressBar bar("hierarchical radiosity (" + std::to_string(base.patches.size()) + " base patches)", 1.0, r.quiet);
    h = solveHierarchical(base, *baseAccel, r.hierarchical, [&](double fraction) {
      reportPhase("hierarchical radiosity", fraction);
      bar.update(fraction);
    });
  }
  auto out = std::make_shared<PatchScene>();
  PatchMesh& mesh = out->mesh;
  std::map<std::tuple<float, float, float, uint32_t>, uint32_t> vertexAt;  // by position, per object
  for (size_t leaf = 0; leaf < h.triangles.size(); ++leaf) {
    const Patch& parent = base.patches[h.basePatch[leaf]];
    Patch p = parent;
    p.fourth = kNoCorner;  // (leaves are triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3& x = h.positions[h.triangles[leaf][k]];
      auto it = vertexAt.find({x.x, x.y, x.z, parent.object});
      if (it == vertexAt.end()) {
        it = vertexAt.emplace(std::make_tuple(x.x, x.y, x.z, parent.object), static_cast<uint32_t>(mesh.positions.size())).first;
        mesh.positions.push_back(x);
      }
      p.vertices[k] = it->second;
    }
    const Vec3 a = mesh.positions[p.vertices.x], b = mesh.positions[p.vertices.y], c = mesh.positions[p.vertices.z];
    p.area = 0.5f * glm::length(glm::cross(b - a, c - a));
    p.centre = (a + b + c) / 3.0f;
    mesh.patches.push_back(p);
  }
  mesh.buildViews();
  out->refinement = {base.patches.size(), mesh.patches.size()};
  out->accel = info.make(ParamSet(info.name, info.params));
  out->accel->build(mesh.geometry);
  out->hierarchy = PatchScene::Hierarchy{base.patches.size(), h.elements, h.links, h.visibilityRays, h.rounds,
                                         h.refineSeconds};
  out->formFactorSeconds = since(start);
  Solution solution;
  solution.radiosity = h.radiosity;
  solution.history = h.history;
  solution.converged = h.converged;
  solution.failure = h.failure;
  solution.seconds = h.solveSeconds;
  return {out, solution};
}

std::shared_ptr<const SolvedRadiosity> computeSolution(std::shared_ptr<const PatchScene> patches,
                                                       const RadiositySettings& r,
                                                       const Solution* solved = nullptr) {
  auto out = std::make_shared<SolvedRadiosity>();
  out->patches = std::move(patches);
  TaskLog log;  // catches the A5.2 / A5.3 stubs
  const ScopedTaskLog scope(&log);
  const RadiositySystem system = out->system();
  if (solved) {
    out->solution = *solved;
  } else {
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
  // The bounce terms need F: hierarchical radiosity shows its solution.
  const RadiositySettings::Show show = solved ? RadiositySettings::Show::Solution : r.show;
  switch (show) {
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
  if (!solved) {
    out->energy = energyBalance(system, b);
  } else {
    // No F to gather with: what arrives at a leaf is H = (B - E) / rho (where rho > 0; a black leaf's
    // absorbed power is not known and not counted), absorbed (1 - rho) H A.
    for (size_t i = 0; i < b.size(); ++i) {
      const Patch& p = mesh.patches[i];
      out->energy.emitted += static_cast<double>(p.area * (p.emission.r + p.emission.g + p.emission.b)) / 3.0;
      for (int c = 0; c < 3; ++c)
        if (p.reflectance[c] > 0.0f)
          out->energy.absorbed += static_cast<double>((1.0f - p.reflectance[c]) * (b[i][c] - p.emission[c]) /
                                                      p.reflectance[c] * p.area) / 3.0;
    }
    out->energy.escaped = out->energy.emitted - out->energy.absorbed;
  }
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
  r.discontinuityMeshing = p.getBool("discontinuity_meshing");
  r.quadPatches = p.getBool("quad_patches");
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
                    : solver == "hierarchical" ? SolverMethod::Hierarchical
                                               : SolverMethod::GaussSeidel;
  r.hierarchical.linkEpsilon = p.getFloat("link_epsilon");
  r.hierarchical.tolerance = r.solver.tolerance;
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
                        std::to_string(settings.discontinuityMeshing) + std::to_string(settings.quadPatches) + "|" +
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
  if (settings.solver.method == SolverMethod::Hierarchical) {
    const HierarchicalPatches h = computeHierarchical(scene, settings);
    return computeSolution(h.patches, settings, &h.solution);
  }
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
  if (settings.solver.method == SolverMethod::Hierarchical) {  // its patches are its solution's: not shared
    auto solved = solveSceneUncached(scene, settings);
    solveCache.emplace_front(sk, solved);
    if (solveCache.size() > 8) solveCache.pop_back();
    return solved;
  }
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
