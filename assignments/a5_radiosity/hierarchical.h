// Hierarchical radiosity (framework code): P. Hanrahan, D. Salzman and
// L. Aupperle, "A Rapid Hierarchical Radiosity Algorithm", SIGGRAPH 1991,
// with their BF refinement (Sec. 4; M. Cohen and J. Wallace, "Radiosity and
// Realistic Image Synthesis", 1993, ch. 7).
//
// Every base patch (a triangle of a PatchMesh) is the root of a quadtree of
// elements (4-way midpoint subdivision). Elements exchange light through
// links: a link (p <- q) stored at receiver p carries F_pq V_pq, the form
// factor from p to q times the fraction of q that p sees. Links start
// between every pair of base patches that face each other and are refined
// -- the larger element of the pair is split and the link replaced by links
// to its four children -- while the power the link carries is too large:
//
//   rho_p A_p F_pq B_q  >  linkEpsilon * sum_i A_i E_i        (watts)
//
// (largest over r, g, b; E_i, B_q in W/m^2 in scene units; F_pq unoccluded,
// so a link is refined as long as it is partly visible and carries much).
// Links that no visibility ray passes are dropped; a link whose rays all
// pass hands "fully visible" on to the links it is refined into (a link
// about to be refined looks with 4x the rays). Then B is solved by Jacobi
// gathering over the links and a push-pull pass (irradiance pushed down to
// the leaves, radiosity pulled up area-weighted) to the tolerance, and the
// links are checked again with the new B (refined when above 1.1 x the
// threshold); rounds repeat until at most 0.1 % of the links are left above
// it (round 0 sees only the emitted light, so there are at least two).
//
// Accuracy: the constant-radiosity links of HR are exact only on average. A
// coarse link spreads what it gathers evenly over its receiver, so near a
// concave edge a leaf's summed form factors can be off by 20-30 % at any
// linkEpsilon, while area-weighted means (per base patch, per object) are
// close; see tests/numerics/hierarchical_radiosity_test.cpp for numbers.
//
// F_pq is estimated by Lambert's contour integral from points of p to q
// (clipped to each point's front half-space), averaged with a degree-2
// triangle quadrature that subdivides p where q is close: finite for
// elements sharing an edge or a vertex. Visibility: `visibilitySamples`
// rays between stratified point pairs, seeded by (seed, p, q), so results do
// not depend on the thread count. Element ids, and so results, are the same
// for any thread count: elements are created in a serial pass, in id order.
//
// Precondition: `base` is coarse (the scene's own polygons, e.g.
// buildPatchMesh(scene, huge maxEdge)): the first links are all pairs of base
// patches, O(N^2); `accel` is built over base.geometry.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "accel/accelerator.h"
#include "patch_mesh.h"
#include "radiosity_solver.h"

namespace ll::a5 {

struct HierarchicalSettings {
  // BF refinement threshold, relative to the emitted power (see above): the most power one link may carry.
  double linkEpsilon = 1e-4;
  // Elements are not split below this fraction of the base mesh's total area.
  double minArea = 1e-6;
  int visibilitySamples = 4;      // rays per link (stratified point pairs)
  size_t maxElements = 4000000;   // no split beyond this many elements (memory bound; reported)
  double tolerance = 1e-4;        // on the relative change of the leaves' B per iteration (see history)
  int maxIterations = 500;        // gather + push-pull iterations per solve
  int maxRounds = 16;             // solve-then-refine rounds
  uint64_t seed = 0;
};

struct HierarchicalResult {
  // The leaves of the element hierarchy as triangles (3 unshared vertices
  // each, wound like their base patch), with their radiosity B (W/m^2) and
  // the base patch each lies in.
  std::vector<Vec3> positions;
  std::vector<glm::uvec3> triangles;
  std::vector<Rgb> radiosity;
  std::vector<uint32_t> basePatch;
  // Per base patch: the area-weighted mean of its leaves (compare with a full-matrix solve on `base`).
  std::vector<Rgb> basePatchRadiosity;
  size_t elements = 0, leaves = 0, links = 0;  // links: those kept at the end (visible, F > 0)
  uint64_t visibilityRays = 0;
  int rounds = 0;  // refinement rounds run
  // Per gather iteration (numbered across rounds): max over leaves of |B_new - B_old| / max B (largest over r, g, b).
  std::vector<SolverStep> history;
  bool converged = false;  // the last solve met the tolerance and no link was left to refine
  std::string failure;     // one line when not converged (or when a non-finite value was caught)
  double refineSeconds = 0.0, solveSeconds = 0.0, seconds = 0.0;
};

// `progress` (may be empty) is called on the calling thread between phases
// with the estimated fraction done; an exception it throws cancels the solve.
HierarchicalResult solveHierarchical(const PatchMesh& base, const Accelerator& accel, const HierarchicalSettings& settings,
                                     const std::function<void(double fraction)>& progress = {});

}  // namespace ll::a5
