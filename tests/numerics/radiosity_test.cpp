// Hard cases of radiosity: patches sharing an edge with a perpendicular
// neighbour (the kernel is singular along it), a patch 1e4 times smaller than
// the scene, and reflectance close to 1 (0.999: the Neumann series converges
// slowly, 1/(1 - rho) = 1000). Form factors stay finite and match closed
// forms; every solver converges to the direct solve with finite radiosity.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "radiosity_scene.h"
#include "radiosity_solver.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

#define SKIP_WITHOUT_SOLUTION() \
  if (!LIGHTLAB_SOLUTION) GTEST_SKIP() << "checks the solution of A5"

Scene sceneFrom(const std::string& objects, const std::string& material = R"({"kd": [0.5, 0.5, 0.5]})") {
  return parseJsonScene(R"({"camera": {"eye": [0.5, 3, 3], "target": [0.5, 0.5, 0.5], "up": [0, 1, 0], "fov_y_deg": 40, "width": 8, "height": 8},
    "materials": {"m": )" + material + R"(}, "objects": [)" + objects + "]}",
                        "radiosity_hard_case.json", ".");
}

// F from object `from` to object `to`: the area-weighted mean over from's patches of their summed F_ij.
double objectFormFactor(const a5::SolvedRadiosity& s, uint32_t from, uint32_t to) {
  double flux = 0.0, area = 0.0;
  for (uint32_t i = 0; i < s.mesh().patches.size(); ++i) {
    if (s.mesh().patches[i].object != from) continue;
    area += static_cast<double>(s.mesh().patches[i].area);
    for (uint32_t k = s.f().rowStart[i]; k < s.f().rowStart[i + 1]; ++k)
      if (s.mesh().patches[s.f().column[k]].object == to)
        flux += static_cast<double>(s.mesh().patches[i].area) * static_cast<double>(s.f().value[k]);
  }
  return flux / area;
}

void expectFiniteFormFactors(const a5::SolvedRadiosity& s) {
  for (size_t k = 0; k < s.f().value.size(); ++k) {
    ASSERT_TRUE(std::isfinite(s.f().value[k])) << "entry " << k;
    ASSERT_GE(s.f().value[k], 0.0f) << "entry " << k;
  }
  EXPECT_LE(s.diagnostics().rowSumMax, 1.0 + 1e-3);
}

a5::RadiositySettings settings(a5::FormFactorMethod method, float patchSize) {
  a5::RadiositySettings r;
  r.patchSize = patchSize;
  r.formFactors.method = method;
  r.formFactors.hemicubeResolution = 32;
  r.formFactors.monteCarloSamples = 16;
  return r;
}

TEST(Numerics_Radiosity, PatchesSharingAnEdgeWithAPerpendicularNeighbour) {
  SKIP_WITHOUT_SOLUTION();
  // Unit squares in z = 0 (facing +z) and y = 0 (facing +y), sharing the edge along x: F = 0.20004 both ways.
  const Scene scene = sceneFrom(R"(
    {"type": "quad", "material": "m", "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]},
    {"type": "quad", "material": "m", "vertices": [[0, 0, 0], [0, 0, 1], [1, 0, 1], [1, 0, 0]]})");
  struct Case {
    a5::FormFactorMethod method;
    double tolerance;
  };
  for (const Case& c : {Case{a5::FormFactorMethod::Analytic, 3e-3}, Case{a5::FormFactorMethod::Hemicube, 1e-2},
                        Case{a5::FormFactorMethod::MonteCarlo, 2e-2}}) {
    SCOPED_TRACE(a5::methodName(c.method));
    const auto s = a5::solveScene(scene, settings(c.method, 0.08f));
    ASSERT_GT(s->mesh().patches.size(), 150u);  // rows of patches right along the shared edge
    expectFiniteFormFactors(*s);
    EXPECT_NEAR(objectFormFactor(*s, 0, 1), 0.20004, c.tolerance);
    EXPECT_NEAR(objectFormFactor(*s, 1, 0), 0.20004, c.tolerance);
    for (const Rgb& b : s->solution.radiosity) ASSERT_TRUE(isFinite(b));
  }
}

TEST(Numerics_Radiosity, APatchTenThousandTimesSmallerThanTheScene) {
  SKIP_WITHOUT_SOLUTION();
  // A 1e-4 square 1 above the centre of a unit square, facing it: 1e-8 of the scene's area.
  // From the tiny patch (a point, to 1e-8): F = 4 * (1/2pi) [2 X/sqrt(1+X^2) atan(X/sqrt(1+X^2))], X = 1/2.
  const double x = 0.5, root = std::sqrt(1.0 + x * x);
  const double expected = 4.0 / (2.0 * static_cast<double>(kPi)) * 2.0 * x / root * std::atan(x / root);  // 0.23947
  const Scene scene = sceneFrom(R"(
    {"type": "quad", "material": "m", "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]},
    {"type": "quad", "material": "m", "vertices": [[0.49995, 0.49995, 1], [0.49995, 0.50005, 1], [0.50005, 0.50005, 1], [0.50005, 0.49995, 1]]})");
  for (const auto method : {a5::FormFactorMethod::Analytic, a5::FormFactorMethod::Hemicube}) {
    SCOPED_TRACE(a5::methodName(method));
    const auto s = a5::solveScene(scene, settings(method, 0.1f));
    expectFiniteFormFactors(*s);
    EXPECT_NEAR(objectFormFactor(*s, 1, 0), expected, method == a5::FormFactorMethod::Analytic ? 1e-3 : 5e-3);
    if (method == a5::FormFactorMethod::Analytic) {
      // Reciprocity: A_big F_big->tiny = A_tiny F_tiny->big, with A_tiny = 1e-8 (the hemicube cannot see it).
      EXPECT_NEAR(objectFormFactor(*s, 0, 1) / 1e-8, objectFormFactor(*s, 1, 0), 0.02 * expected);
    }
  }
}

// A closed unit cube, faces wound inwards, every face emitting and reflecting rho.
Scene closedCube(float rho) {
  const std::string r = std::to_string(rho);
  return sceneFrom(R"(
    {"type": "quad", "material": "m", "vertices": [[0,0,0], [1,0,0], [1,1,0], [0,1,0]]},
    {"type": "quad", "material": "m", "vertices": [[0,0,1], [0,1,1], [1,1,1], [1,0,1]]},
    {"type": "quad", "material": "m", "vertices": [[0,0,0], [0,1,0], [0,1,1], [0,0,1]]},
    {"type": "quad", "material": "m", "vertices": [[1,0,0], [1,0,1], [1,1,1], [1,1,0]]},
    {"type": "quad", "material": "m", "vertices": [[0,0,0], [0,0,1], [1,0,1], [1,0,0]]},
    {"type": "quad", "material": "m", "vertices": [[0,1,0], [1,1,0], [1,1,1], [0,1,1]]})",
                   R"({"kd": [)" + r + ", " + r + ", " + r + R"(], "emission": [1, 1, 1]})");
}

TEST(Numerics_Radiosity, ReflectanceCloseToOneConvergesToTheDirectSolve) {
  SKIP_WITHOUT_SOLUTION();
  const Scene scene = closedCube(0.999f);
  a5::RadiositySettings r = settings(a5::FormFactorMethod::Analytic, 0.4f);
  r.solver.method = a5::SolverMethod::Direct;
  const auto direct = a5::solveScene(scene, r);
  expectFiniteFormFactors(*direct);
  // The Neumann bound: B <= E / (1 - rho max_i sum_j F_ij), and at least E / (1 - rho min_i sum_j F_ij).
  const double e = static_cast<double>(kPi), rho = 0.999;
  double peak = 0.0;
  for (const Rgb& b : direct->solution.radiosity) {
    ASSERT_TRUE(isFinite(b));
    EXPECT_LE(b.r, e / (1.0 - rho * direct->diagnostics().rowSumMax) * (1.0 + 1e-3));
    EXPECT_GE(b.r, e / (1.0 - rho * direct->diagnostics().rowSumMin) * (1.0 - 1e-3));
    peak = std::max(peak, static_cast<double>(b.r));
  }
  EXPECT_GT(peak, 100.0 * e);  // light bounces ~1000 times: B is hundreds of times E
  for (const auto method : {a5::SolverMethod::Jacobi, a5::SolverMethod::GaussSeidel, a5::SolverMethod::Southwell}) {
    SCOPED_TRACE(a5::methodName(method));
    r.solver.method = method;
    // B ~ 3000 in float: a relative residual of 5e-4 is B to ~1e-3. Southwell's criterion is the unshot
    // power over the emitted, which 1 / (1 - rho) = 1000 amplifies: it needs 1e-6.
    r.solver.tolerance = method == a5::SolverMethod::Southwell ? 1e-6 : 5e-4;
    r.solver.maxIterations = 40000;
    const auto s = a5::solveScene(scene, r);
    EXPECT_TRUE(s->solution.converged);
    // Southwell shoots with F_ji = F_ij A_i / A_j: the direct solve's system only as far as F is reciprocal,
    // and 1 / (1 - rho) amplifies the difference (A5_Solvers allows 3e-2 on the Cornell box).
    const float tolerance = method == a5::SolverMethod::Southwell ? 3e-2f : 2e-3f;
    for (size_t i = 0; i < s->solution.radiosity.size(); ++i) {
      ASSERT_TRUE(isFinite(s->solution.radiosity[i]));
      EXPECT_NEAR(s->solution.radiosity[i].r, direct->solution.radiosity[i].r, tolerance * direct->solution.radiosity[i].r)
          << "patch " << i;
    }
  }
}

}  // namespace
}  // namespace ll
