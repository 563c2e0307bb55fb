#include "radiosity_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <Eigen/Dense>

#include "core/error.h"

namespace ll::a5 {

namespace {

double elapsed(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Rgb gather(const FormFactors& f, uint32_t i, const std::vector<Rgb>& b) {
  Rgb g(0.0f);
  for (uint32_t k = f.rowStart[i]; k < f.rowStart[i + 1]; ++k) g += f.value[k] * b[f.column[k]];
  return g;
}

std::vector<Rgb> directSolve(const RadiositySystem& s) {
  const size_t n = s.f.size();
  if (n > kDirectMaxPatches)
    throwUserError("solver 'direct': " + std::to_string(n) + " patches, more than the dense LU's limit of " +
                   std::to_string(kDirectMaxPatches) + " (allowed: direct up to that; jacobi, gauss-seidel, southwell)");
  std::vector<Rgb> b(n, Rgb(0.0f));
  const auto dim = static_cast<Eigen::Index>(n);
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd m = Eigen::MatrixXd::Identity(dim, dim);
    Eigen::VectorXd e(dim);
    for (uint32_t i = 0; i < n; ++i) {
      const double rho = s.patches[i].reflectance[c];
      e(i) = s.patches[i].emission[c];
      for (uint32_t k = s.f.rowStart[i]; k < s.f.rowStart[i + 1]; ++k) m(i, s.f.column[k]) -= rho * static_cast<double>(s.f.value[k]);
    }
    const Eigen::VectorXd x = m.partialPivLu().solve(e);
    for (uint32_t i = 0; i < n; ++i) b[i][c] = static_cast<float>(x(i));
  }
  return b;
}

}  // namespace

std::string methodName(SolverMethod m) {
  switch (m) {
    case SolverMethod::Direct: return "direct";
    case SolverMethod::Jacobi: return "jacobi";
    case SolverMethod::GaussSeidel: return "gauss-seidel";
    case SolverMethod::Southwell: return "southwell";
  }
  return "";
}

double residual(const RadiositySystem& s, const std::vector<Rgb>& b) {
  double worst = 0.0, emitted = 0.0;
  for (uint32_t i = 0; i < s.f.size(); ++i) {
    const Patch& p = s.patches[i];
    const Rgb r = p.emission + p.reflectance * gather(s.f, i, b) - b[i];
    worst = std::max(worst, static_cast<double>(maxComponent(glm::abs(r))));
    emitted = std::max(emitted, static_cast<double>(maxComponent(p.emission)));
  }
  return emitted > 0.0 ? worst / emitted : worst;
}

std::vector<Rgb> bounce(const RadiositySystem& s, int k) {
  std::vector<Rgb> b(s.f.size());
  for (uint32_t i = 0; i < b.size(); ++i) b[i] = s.patches[i].emission;
  for (int step = 0; step < k; ++step) {
    std::vector<Rgb> next(b.size());
    for (uint32_t i = 0; i < b.size(); ++i) next[i] = s.patches[i].reflectance * gather(s.f, i, b);
    b.swap(next);
  }
  return b;
}

EnergyBalance energyBalance(const RadiositySystem& s, const std::vector<Rgb>& b) {
  EnergyBalance e;
  for (uint32_t i = 0; i < s.f.size(); ++i) {
    const Patch& p = s.patches[i];
    const Rgb arriving = gather(s.f, i, b);  // irradiance H_i = sum_j F_ij B_j (by reciprocity)
    e.emitted += static_cast<double>(p.area * (p.emission.r + p.emission.g + p.emission.b)) / 3.0;
    const Rgb absorbed = (Rgb(1.0f) - p.reflectance) * arriving * p.area;
    e.absorbed += static_cast<double>(absorbed.r + absorbed.g + absorbed.b) / 3.0;
  }
  e.escaped = e.emitted - e.absorbed;
  return e;
}

Solution solveRadiosity(const RadiositySystem& s, const SolverSettings& settings,
                        const std::function<void(const SolverStep&)>& onStep) {
  const auto start = std::chrono::steady_clock::now();
  const size_t n = s.f.size();
  Solution out;
  out.radiosity.resize(n);
  for (uint32_t i = 0; i < n; ++i) out.radiosity[i] = s.patches[i].emission;
  const auto record = [&](int iteration) {
    const SolverStep step{iteration, residual(s, out.radiosity), elapsed(start)};
    out.history.push_back(step);
    if (onStep) onStep(step);
    return step.residual;
  };
  record(0);
  switch (settings.method) {
    case SolverMethod::Direct:
      out.radiosity = directSolve(s);
      record(1);
      out.converged = true;  // exact up to rounding (the residual shows how much)
      break;
    case SolverMethod::Jacobi:
    case SolverMethod::GaussSeidel:
      for (int it = 1; it <= settings.maxIterations; ++it) {
        if (settings.method == SolverMethod::GaussSeidel) {
          gaussSeidelSweep(s, out.radiosity);
        } else {
          std::vector<Rgb> next(n);
          for (uint32_t i = 0; i < n; ++i)
            next[i] = s.patches[i].emission + s.patches[i].reflectance * gather(s.f, i, out.radiosity);
          out.radiosity.swap(next);
        }
        if (record(it) <= settings.tolerance) {
          out.converged = true;
          break;
        }
      }
      break;
    case SolverMethod::Southwell: {
      // Its residual is the unshot power over the emitted power: what shooting
      // has left to do. (Shooting spreads row i by reciprocity, F_ji = F_ij
      // A_i / A_j, so where F is not exactly reciprocal it converges to a
      // slightly different B than gathering; the gathering residual then stalls.)
      out.unshot = out.radiosity;  // everything emitted is still to be shot
      const auto unshotFraction = [&] {
        double left = 0.0, emitted = 0.0;
        for (uint32_t i = 0; i < n; ++i) {
          left += static_cast<double>(maxComponent(out.unshot[i]) * s.patches[i].area);
          emitted += static_cast<double>(maxComponent(s.patches[i].emission) * s.patches[i].area);
        }
        return emitted > 0.0 ? left / emitted : 0.0;
      };
      out.history.back().residual = unshotFraction();
      const size_t shotsPerIteration = std::max<size_t>(n, 1);
      for (int it = 1; it <= settings.maxIterations && !out.converged; ++it) {
        bool exhausted = false;
        for (size_t k = 0; k < shotsPerIteration && !exhausted; ++k) exhausted = shootLargest(s, out.radiosity, out.unshot) < 0;
        const SolverStep step{it, unshotFraction(), elapsed(start)};
        out.history.push_back(step);
        if (onStep) onStep(step);
        out.converged = step.residual <= settings.tolerance;
        if (exhausted) break;  // nothing left to shoot (or the stand-in of A5.3 shoots nothing)
      }
      // The ambient term (Cohen et al. 1988): the unshot radiosity, spread
      // evenly and reflected over and over with the mean reflectance.
      double area = 0.0;
      Rgb unshotPower(0.0f), rhoMean(0.0f);
      for (uint32_t i = 0; i < n; ++i) {
        area += static_cast<double>(s.patches[i].area);
        unshotPower += out.unshot[i] * s.patches[i].area;
        rhoMean += s.patches[i].reflectance * s.patches[i].area;
      }
      if (area > 0.0) {
        rhoMean /= static_cast<float>(area);
        out.ambient = unshotPower / static_cast<float>(area) / glm::max(Rgb(1.0f) - rhoMean, Rgb(1e-3f));
      }
      break;
    }
  }
  out.seconds = elapsed(start);
  return out;
}

}  // namespace ll::a5
