// Form factors F_ij -- the fraction of the power leaving patch i (diffusely,
// from its front side) that arrives at patch j -- stored as a sparse matrix,
// by three methods (framework code around task A5.1):
//   analytic:    the point-to-polygon form factor (Lambert's contour
//                integral, A5.1) from i's centre to j clipped to i's front
//                half-space, times the fraction of visibility rays from
//                i's centre to points on j that arrive;
//   hemicube:    a hemicube of res x res cells on the top face around i's
//                centre, turned about i's normal by a random angle per
//                patch, each cell's delta form factor (normalised: they sum
//                to 1) given to the patch its centre ray hits first (cast
//                through the accelerator);
//   montecarlo:  area-to-area, finite variance next to shared edges: N
//                stratified points x on i, at each the point-to-polygon
//                form factor (A5.1) to j minus a one-ray estimate of the
//                part of it that is hidden (see monteCarloRow).
// Every visibility test goes through `accel` (built over mesh.geometry).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "accel/accelerator.h"
#include "patch_mesh.h"

namespace ll::a5 {

enum class FormFactorMethod { Analytic, Hemicube, MonteCarlo };

struct FormFactorSettings {
  FormFactorMethod method = FormFactorMethod::Hemicube;
  int hemicubeResolution = 32;  // cells along the top face's side
  int visibilitySamples = 1;    // analytic: rays from i's centre to points on j
  int monteCarloSamples = 16;   // montecarlo: points on i (and visibility rays) per patch pair
  uint64_t seed = 0;            // montecarlo's points, the hemicubes' turns
};

// Row i: the patches j with F_ij > 0 and their F_ij (sorted by j).
struct FormFactors {
  std::vector<uint32_t> rowStart;  // size N + 1
  std::vector<uint32_t> column;
  std::vector<float> value;
  size_t size() const { return rowStart.empty() ? 0 : rowStart.size() - 1; }
  float at(uint32_t i, uint32_t j) const;  // 0 where not stored
};

// Checks of a computed matrix: each row sums to at most 1 (exactly 1 in a
// closed scene), and A_i F_ij = A_j F_ji (reciprocity).
struct FormFactorDiagnostics {
  double rowSumMin = 0.0, rowSumMean = 0.0, rowSumMax = 0.0;
  double reciprocityMeanError = 0.0;  // sum |A_i F_ij - A_j F_ji| / sum A_i F_ij (weighted by what is exchanged)
  double reciprocityMaxError = 0.0;   // max of |A_i F_ij - A_j F_ji| / max(A_i F_ij, A_j F_ji) where F_ij or F_ji > 0.01
  size_t nonZeros = 0;
  uint64_t visibilityRays = 0;
};

// `progress(done, total)` (may be empty) is called from worker threads as rows finish.
FormFactors computeFormFactors(const PatchMesh& mesh, const Accelerator& accel, const FormFactorSettings& settings,
                               FormFactorDiagnostics* diagnostics = nullptr,
                               const std::function<void(size_t, size_t)>& progress = {});

// Rows of the hemicube method one at a time (progressive refinement
// computes a row only when its patch shoots). Not thread-safe.
struct FormFactorEntry {
  uint32_t j;
  float f;
};
class HemicubeRows {
 public:
  // seed: the hemicubes' random turns about the normals (as computeFormFactors with that seed).
  HemicubeRows(const PatchMesh& mesh, const Accelerator& accel, int resolution, uint64_t seed = 0);
  ~HemicubeRows();
  // F_ij for every patch j the hemicube of patch i sees, sorted by j.
  std::vector<FormFactorEntry> row(uint32_t i);
  uint64_t rays() const { return rays_; }

 private:
  const PatchMesh& mesh_;
  const Accelerator& accel_;
  struct Cells;
  std::unique_ptr<Cells> cells_;
  std::vector<float> accumulator_;
  uint64_t seed_ = 0;
  uint64_t rays_ = 0;
};

// The closed form for two parallel coaxial squares of side a at distance h
// (Hottel), and for perpendicular rectangles sharing an edge, for tests and
// slides. F from the first to the second.
double parallelSquaresFormFactor(double a, double h);
double perpendicularRectanglesFormFactor(double sharedEdge, double width1, double width2);

std::string methodName(FormFactorMethod m);

// Whether the segment from x (on a patch with unit normal nx) to y (on one with normal ny) is
// unobstructed. The ends are offset off their surfaces and the segment is trimmed by kSegmentTrim of
// its length at both ends: the offsets (~1e-5 units) are below the float resolution of t along a
// 500-unit segment, so without the trim the two patches themselves were hit (the Cornell box's
// analytic row sums averaged 0.804 with our BVH and 0.737 with Embree; 0.816 with both now).
constexpr float kSegmentTrim = 1e-4f;
bool visibleBetween(const Accelerator& accel, const Vec3& x, const Vec3& nx, const Vec3& y, const Vec3& ny,
                    QueryCounters& q);

}  // namespace ll::a5
