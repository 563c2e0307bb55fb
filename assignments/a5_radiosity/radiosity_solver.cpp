#include "radiosity_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

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

// Dense LU per channel; `rcond` gets the smallest reciprocal condition
// number estimate of the three (near 0: singular).
std::vector<Rgb> directSolve(const RadiositySystem& s, double& rcond) {
  const size_t n = s.f.size();
  if (n > kDirectMaxPatches)
    throwUserError("solver 'direct': " + std::to_string(n) + " patches, more than the dense LU's limit of " +
                   std::to_string(kDirectMaxPatches) + " (allowed: direct up to that; jacobi, gauss-seidel, southwell)");
  std::vector<Rgb> b(n, Rgb(0.0f));
  rcond = 1.0;
  const auto dim = static_cast<Eigen::Index>(n);
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd m = Eigen::MatrixXd::Identity(dim, dim);
    Eigen::VectorXd e(dim);
    for (uint32_t i = 0; i < n; ++i) {
      const double rho = s.patches[i].reflectance[c];
      e(i) = s.patches[i].emission[c];
      for (uint32_t k = s.f.rowStart[i]; k < s.f.rowStart[i + 1]; ++k) m(i, s.f.column[k]) -= rho * static_cast<double>(s.f.value[k]);
    }
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu = m.partialPivLu();
    rcond = std::min(rcond, lu.rcond());
    const Eigen::VectorXd x = lu.solve(e);
    for (uint32_t i = 0; i < n; ++i) b[i][c] = static_cast<float>(x(i));
  }
  return b;
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

// What is wrong with the input, if anything: the first non-finite emission,
// reflectance or form factor.
std::string inputProblem(const RadiositySystem& s) {
  for (uint32_t i = 0; i < s.f.size(); ++i) {
    if (!isFinite(s.patches[i].emission)) return "patch " + std::to_string(i) + "'s emission is not finite";
    if (!isFinite(s.patches[i].reflectance)) return "patch " + std::to_string(i) + "'s reflectance is not finite";
    for (uint32_t k = s.f.rowStart[i]; k < s.f.rowStart[i + 1]; ++k)
      if (!std::isfinite(s.f.value[k]))
        return "form factor F(" + std::to_string(i) + ", " + std::to_string(s.f.column[k]) + ") is not finite";
  }
  return "";
}

// max over i and channels of rho_i sum_j F_ij, and the patch where it is.
double largestRowGain(const RadiositySystem& s, uint32_t& where) {
  double gain = 0.0;
  where = 0;
  for (uint32_t i = 0; i < s.f.size(); ++i) {
    double sum = 0.0;
    for (uint32_t k = s.f.rowStart[i]; k < s.f.rowStart[i + 1]; ++k) sum += static_cast<double>(s.f.value[k]);
    const double g = sum * static_cast<double>(maxComponent(s.patches[i].reflectance));
    if (g > gain) {
      gain = g;
      where = i;
    }
  }
  return gain;
}

}  // namespace

std::string methodName(SolverMethod m) {
  switch (m) {
    case SolverMethod::Direct: return "direct";
    case SolverMethod::Jacobi: return "jacobi";
    case SolverMethod::GaussSeidel: return "gauss-seidel";
    case SolverMethod::Southwell: return "southwell";
    case SolverMethod::Hierarchical: return "hierarchical";
  }
  return "";
}

double residual(const RadiositySystem& s, const std::vector<Rgb>& b) {
  double worst = 0.0, emitted = 0.0;
  for (uint32_t i = 0; i < s.f.size(); ++i) {
    const Patch& p = s.patches[i];
    const Rgb r = p.emission + p.reflectance * gather(s.f, i, b) - b[i];
    const double w = isFinite(r) ? static_cast<double>(maxComponent(glm::abs(r))) : std::nan("");
    if (!(w <= worst)) worst = w;  // (a NaN stays: std::max would drop it and report convergence)
    if (std::isnan(w)) break;
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
  uint32_t gainPatch = 0;
  out.largestRowGain = largestRowGain(s, gainPatch);
  // Why a system that is not a contraction fails, for the failure's line.
  const std::string contraction =
      out.largestRowGain >= 1.0
          ? "; rho F is not a contraction: row " + std::to_string(gainPatch) + " of rho F sums to " +
                number(out.largestRowGain) +
                (out.largestRowGain > 1.0 + 1e-3 ? " (form factors whose rows sum to more than 1)"
                                                 : " (reflectance 1 in a closed scene: light never leaves)")
          : "";
  const auto finish = [&] {
    for (Rgb& b : out.radiosity)
      if (!isFinite(b)) b = Rgb(0.0f);  // no NaN past the solver; the failure says why
    for (Rgb& u : out.unshot)
      if (!isFinite(u)) u = Rgb(0.0f);
    if (!isFinite(out.ambient)) out.ambient = Rgb(0.0f);
    out.seconds = elapsed(start);
    return out;
  };
  if (const std::string problem = inputProblem(s); !problem.empty()) {
    out.failure = "not solved: " + problem;
    return finish();
  }
  const auto record = [&](int iteration) {
    const SolverStep step{iteration, residual(s, out.radiosity), elapsed(start)};
    out.history.push_back(step);
    if (onStep) onStep(step);
    return step.residual;
  };
  const double first = record(0);
  // An iterate is hopeless when it is no longer finite or its residual has grown a millionfold.
  const auto diverged = [&](double r, int iteration) {
    if (!std::isfinite(r)) {
      out.failure = "diverged: the radiosity became NaN or infinite at iteration " + std::to_string(iteration) +
                    contraction;
      return true;
    }
    if (r > 1e6 * std::max(first, 1e-6)) {
      out.failure = "diverged: the residual grew from " + number(first) + " to " + number(r) + " in " +
                    std::to_string(iteration) + " iterations" + contraction;
      return true;
    }
    return false;
  };
  const auto capReached = [&](double r) {
    out.failure = "not converged after " + std::to_string(settings.maxIterations) + " iterations: residual " +
                  number(r) + " is above the tolerance " + number(settings.tolerance) + contraction;
  };
  switch (settings.method) {
    case SolverMethod::Hierarchical:
      throwUserError("solver 'hierarchical' solves its own elements (solveScene), not a given matrix");
    case SolverMethod::Direct: {
      double rcond = 1.0;
      out.radiosity = directSolve(s, rcond);
      const double r = record(1);
      float lowest = 0.0f, highest = 0.0f;
      uint32_t lowestPatch = 0;
      for (uint32_t i = 0; i < n; ++i) {
        highest = std::max(highest, maxComponent(out.radiosity[i]));
        const float low = std::min(out.radiosity[i].r, std::min(out.radiosity[i].g, out.radiosity[i].b));
        if (low < lowest) {
          lowest = low;
          lowestPatch = i;
        }
      }
      if (!std::isfinite(r) || rcond < 1e-12 || r > std::max(settings.tolerance, 1e-3))
        out.failure = "the system is singular or nearly so (reciprocal condition number " + number(rcond) +
                      ", residual " + number(r) + ")" + contraction;
      else if (lowest < -1e-4f * std::max(highest, 1e-20f))
        out.failure = "negative radiosity " + number(lowest) + " at patch " + std::to_string(lowestPatch) + contraction;
      out.converged = out.failure.empty();
      break;
    }
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
        const double r = record(it);
        if (r <= settings.tolerance) {
          out.converged = true;
          break;
        }
        if (diverged(r, it)) break;
        if (it == settings.maxIterations) capReached(r);
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
          left += isFinite(out.unshot[i]) ? static_cast<double>(maxComponent(out.unshot[i]) * s.patches[i].area)
                                          : std::nan("");
          emitted += static_cast<double>(maxComponent(s.patches[i].emission) * s.patches[i].area);
        }
        return emitted > 0.0 ? left / emitted : left;
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
        if (out.converged || diverged(step.residual, it)) break;
        if (exhausted) {  // nothing left to shoot (or the stand-in of A5.3 shoots nothing)
          out.failure = "stopped at iteration " + std::to_string(it) + ": no patch has unshot power, yet " +
                        number(step.residual) + " of the emitted power is unshot";
          break;
        }
        if (it == settings.maxIterations) capReached(step.residual);
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
  for (const Rgb& b : out.radiosity)
    if (!isFinite(b) && out.failure.empty()) {
      out.converged = false;
      out.failure = "the radiosity is NaN or infinite" + contraction;
    }
  return finish();
}

}  // namespace ll::a5
