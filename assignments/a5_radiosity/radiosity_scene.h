// A scene prepared for radiosity and solved (framework code): the patch
// mesh, an accelerator over the patches, the form factors with their
// diagnostics, and the solution -- everything the display, the command line
// and the tests read. Solving is independent of the camera, so the result is
// cached: moving the camera never recomputes it; changing the scene's
// geometry or materials, the meshing, the form factors or the solver does.
#pragma once

#include <map>
#include <optional>
#include <memory>
#include <string>

#include "core/params.h"
#include "form_factors.h"
#include "hierarchical.h"
#include "progressive.h"
#include "radiosity_solver.h"

namespace ll::a5 {

struct RadiositySettings {
  float patchSize = 0.04f;  // longest patch edge, as a fraction of the scene's bounding-box diagonal
  bool discontinuityMeshing = true;  // cut planar objects along what lies on them first (patch_mesh.h)
  bool quadPatches = true;           // planar quads (not cut) as grids of quad patches (patch_mesh.h)
  // Adaptive refinement: this many rounds of (form factors, solve, split every
  // patch whose radiosity differs from a neighbour's by more than the
  // threshold, relative to the brighter), before the final form factors.
  int adaptivePasses = 0;
  float adaptiveThreshold = 0.25f;
  int sphereSegments = 24;
#ifdef LIGHTLAB_HAVE_EMBREE
  std::string accelerator = "embree";  // for the visibility rays (and the display); see radiosity_technique.cpp
#else
  std::string accelerator = "bvh";
#endif
  FormFactorSettings formFactors;
  SolverSettings solver;
  HierarchicalSettings hierarchical;  // solver = hierarchical: links and elements instead of F (hierarchical.h)
  // What the display shows: the solution, bounce k alone (E, K E, K^2 E, ...), or bounces 0..k summed.
  enum class Show { Solution, Bounce, Bounces } show = Show::Solution;
  int bounce = 1;
  bool progressive = false;  // Southwell with rows computed per shot; each render pass shoots more
  bool quiet = true;  // progress bars on the terminal
};

// Reads the technique's parameters (see radiosity_technique.cpp).
RadiositySettings radiositySettings(const ParamSet& params);

// The patches and their form factors: what depends on the geometry, the
// materials and the meshing/form-factor settings, not on the solver.
struct PatchScene {
  PatchMesh mesh;
  std::vector<size_t> refinement;  // patches after meshing and after each adaptive round
  std::unique_ptr<Accelerator> accel;  // over mesh.geometry
  FormFactors f;  // empty for solver = hierarchical (its links are not a matrix)
  FormFactorDiagnostics diagnostics;
  // solver = hierarchical: the leaves of its element hierarchy are the mesh, and these its counts.
  struct Hierarchy {
    size_t basePatches = 0, elements = 0, links = 0;
    uint64_t visibilityRays = 0;
    int rounds = 0;
    double refineSeconds = 0.0;
  };
  std::optional<Hierarchy> hierarchy;
  double meshSeconds = 0.0, accelSeconds = 0.0, formFactorSeconds = 0.0;
  std::map<std::string, std::string> missingTasks;  // student stubs that ran (A5.1)
  std::map<std::string, bool> tasksRan;              // student tasks called -> by their reference (TaskLog::ran)
};

struct SolvedRadiosity {
  std::shared_ptr<const PatchScene> patches;  // shared by every solve of the same patches
  const PatchMesh& mesh() const { return patches->mesh; }
  const FormFactors& f() const { return patches->f; }
  const Accelerator& accel() const { return *patches->accel; }
  const FormFactorDiagnostics& diagnostics() const { return patches->diagnostics; }
  Solution solution;
  std::vector<Rgb> shown;       // per patch: the radiosity displayed (solution + ambient, or bounces)
  std::vector<Rgb> vertexShown; // per mesh vertex: area-weighted mean of its patches' `shown`
  EnergyBalance energy;
  std::map<std::string, std::string> missingTasks;  // student stubs that ran (A5.x), form factors included
  std::map<std::string, bool> tasksRan;              // student tasks called -> by their reference, likewise
  // Tells the current render (its task log) what this cached solve ran: its stubs and whose code.
  void replayTasks() const;
  RadiositySystem system() const { return {mesh().patches, f()}; }
};

// Solves `scene` (cached by the scene's content and the settings; the
// patches and form factors are cached apart, so changing only the solver or
// the display reuses them).
std::shared_ptr<const SolvedRadiosity> solveScene(const Scene& scene, const RadiositySettings& settings);
// Progressive refinement: the patches (no form-factor matrix) and the shared
// state of their Southwell iteration, rows computed as patches shoot (cached
// like solveScene: a new render of the same scene continues where it stands).
struct ProgressiveScene {
  std::shared_ptr<const PatchScene> patches;  // mesh and accelerator; f stays empty
  std::shared_ptr<ProgressiveRadiosity> state;
};
ProgressiveScene progressiveScene(const Scene& scene, const RadiositySettings& settings);

// The same without the cache: every phase runs (benchmarks).
std::shared_ptr<const SolvedRadiosity> solveSceneUncached(const Scene& scene, const RadiositySettings& settings);

}  // namespace ll::a5
