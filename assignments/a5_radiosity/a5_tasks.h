// Assignment 5 -- Radiosity. The three functions you write, each in its own
// .cpp file between the markers of its task ID; the technique `radiosity`
// and `lightlab radiosity` call them. Until you write one, its stub reports
// the task as missing and the task's reference (the course's solution, object
// code) answers in its place, the picture striped, so the tasks can be done
// in any order. See README.md for the handout and the --reference switches.
#pragma once

#include <vector>

#include "core/math.h"
#include "form_factors.h"
#include "patch_mesh.h"

namespace ll::a5 {

// A5.1 Point-to-polygon form factor (Lambert 1760; Nusselt's analogy): the
// fraction of the power leaving a differential area at x with unit normal n
// that arrives at the polygon `vertices` (count >= 3, convex or not, either
// winding), assuming nothing is in between and the whole polygon lies on n's
// side (x's plane clips it before the call):
//   F = (1 / 2 pi) | sum over edges k of  beta_k  n . (r_k x r_k+1) / |r_k x r_k+1| |
// with r_k = v_k - x and beta_k the angle between r_k and r_k+1 (radians).
float pointToPolygonFormFactor(Vec3 x, Vec3 n, const Vec3* vertices, int count);

// The linear system of radiosity, B = E + rho (F B), per colour channel.
struct RadiositySystem {
  const std::vector<Patch>& patches;  // area, emission E, reflectance rho
  const FormFactors& f;
};

// A5.2 One Gauss-Seidel sweep: for i = 0 .. N-1 in order,
//   B_i = E_i + rho_i * sum_j F_ij B_j
// using the B_j already updated in this sweep. Returns the largest change of
// any B_i (largest over r, g, b).
float gaussSeidelSweep(const RadiositySystem& system, std::vector<Rgb>& b);

// A5.3 One step of progressive refinement (Southwell, "shooting"): the patch
// i with the largest unshot power maxComponent(unshot_i) * A_i shoots it: for
// every j in row i of F, the radiosity j receives is
//   dB = rho_j * F_ji * unshot_i,  with F_ji = F_ij A_i / A_j (reciprocity),
// added to both b_j and unshot_j; then unshot_i = 0. Returns i, or -1 if no
// patch has unshot power left.
int shootLargest(const RadiositySystem& system, std::vector<Rgb>& b, std::vector<Rgb>& unshot);

}  // namespace ll::a5
