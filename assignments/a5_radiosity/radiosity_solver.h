// Solving B = E + rho (F B) for the patch radiosities B (framework code
// around tasks A5.2 and A5.3), with the residual history:
//   direct:       (I - diag(rho_c) F) B_c = E_c per channel, dense LU with
//                 partial pivoting (Eigen); N <= kDirectMaxPatches;
//   jacobi:       B <- E + rho F B, all from the previous iterate;
//   gauss-seidel: the same in place (A5.2);
//   southwell:    progressive refinement, shooting the largest unshot power
//                 (A5.3); N shots count as one iteration in the history, and
//                 its residual is the unshot power over the emitted power.
// The residual is max_i |E_i + rho_i (F B)_i - B_i| / max_i E_i (largest
// over r, g, b; NaN if any B is): iterative solvers stop when it is below the
// tolerance, or at the iteration cap.
//
// A solve that fails says why in one line (Solution::failure): input that is
// not finite, a radiosity that became NaN or Inf, a residual that grows
// (rho F is not a contraction: a row of it sums to 1 or more), a singular or
// near-singular system (direct), negative radiosities (direct, on a system
// that is not a contraction), or the iteration cap. No NaN or Inf is ever
// returned: such values become 0 and the failure names them.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "a5_tasks.h"

namespace ll::a5 {

// Hierarchical is solved by hierarchical.h on elements of its own (radiosity_scene.cpp), not by solveRadiosity.
enum class SolverMethod { Direct, Jacobi, GaussSeidel, Southwell, Hierarchical };
constexpr size_t kDirectMaxPatches = 3000;

struct SolverSettings {
  SolverMethod method = SolverMethod::GaussSeidel;
  double tolerance = 1e-4;  // on the relative residual
  int maxIterations = 1000;
};

struct SolverStep {
  int iteration = 0;
  double residual = 0.0;
  double seconds = 0.0;  // since the solve began
};

struct Solution {
  std::vector<Rgb> radiosity;  // B per patch
  std::vector<Rgb> unshot;     // southwell: what is left to shoot (else empty)
  Rgb ambient{0.0f};           // southwell: the ambient estimate of the unshot part, for display
  std::vector<SolverStep> history;
  bool converged = false;
  std::string failure;  // why not converged, one line (empty when converged)
  double largestRowGain = 0.0;  // max over patches and channels of rho_i sum_j F_ij (< 1: a contraction)
  double seconds = 0.0;
};

// `onStep` (may be empty) sees every recorded step, e.g. for a progress bar.
Solution solveRadiosity(const RadiositySystem& system, const SolverSettings& settings,
                        const std::function<void(const SolverStep&)>& onStep = {});

// The relative residual of B (see above).
double residual(const RadiositySystem& system, const std::vector<Rgb>& b);

// The k-th term of the Neumann series: bounce 0 = E, bounce k = rho F (bounce k-1).
std::vector<Rgb> bounce(const RadiositySystem& system, int k);

// Power balance (radiosity x area, summed): emitted, absorbed by the patches
// ((1 - rho) B A... of what arrives), and what leaves the scene through its openings.
struct EnergyBalance {
  double emitted = 0.0, absorbed = 0.0, escaped = 0.0;
};
EnergyBalance energyBalance(const RadiositySystem& system, const std::vector<Rgb>& b);

std::string methodName(SolverMethod m);

}  // namespace ll::a5
