#include "metrics/chi_square.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

namespace ll {

namespace {

// Regularised lower incomplete gamma P(a, x) by its series, for x < a + 1.
double gammaSeries(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 10000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-15) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Regularised upper incomplete gamma Q(a, x) by its continued fraction (modified Lentz), for x >= a + 1.
double gammaContinuedFraction(double a, double x) {
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

// Adaptive Simpson over [a, c] to absolute accuracy about eps, at most 2^maxDepth panels deep (Lyness
// 1969's stopping rule with Richardson extrapolation, as pbrt-v3's BSDF tests integrate).
double adaptiveSimpson(const std::function<double(double)>& f, double a, double c, double eps, int maxDepth) {
  const std::function<double(double, double, double, double, double, double, double, double, int)> step =
      [&](double x0, double x1, double x2, double f0, double f1, double f2, double whole, double e, int depth) {
        const double xa = 0.5 * (x0 + x1), xb = 0.5 * (x1 + x2), fa = f(xa), fb = f(xb);
        const double h = x2 - x0;
        const double left = h / 12.0 * (f0 + 4.0 * fa + f1), right = h / 12.0 * (f1 + 4.0 * fb + f2);
        const double both = left + right;
        if (depth <= 0 || std::abs(both - whole) < 15.0 * e) return both + (both - whole) / 15.0;
        return step(x0, xa, x1, f0, fa, f1, left, 0.5 * e, depth - 1) +
               step(x1, xb, x2, f1, fb, f2, right, 0.5 * e, depth - 1);
      };
  // Four panels to start, so that a narrow peak between the first samples is not missed.
  double sum = 0.0;
  for (int i = 0; i < 4; ++i) {
    const double x0 = a + (c - a) * i / 4.0, x2 = a + (c - a) * (i + 1) / 4.0, x1 = 0.5 * (x0 + x2);
    const double f0 = f(x0), f1 = f(x1), f2 = f(x2);
    sum += step(x0, x1, x2, f0, f1, f2, (x2 - x0) / 6.0 * (f0 + 4.0 * f1 + f2), 0.25 * eps, maxDepth);
  }
  return sum;
}

}  // namespace

double chiSquareSurvival(double x, int dof) {
  if (dof <= 0) return 1.0;
  if (!(x > 0.0)) return 1.0;
  const double a = 0.5 * dof, y = 0.5 * x;
  return y < a + 1.0 ? 1.0 - gammaSeries(a, y) : gammaContinuedFraction(a, y);
}

std::string ChiSquareResult::summary() const {
  std::ostringstream s;
  s << std::setprecision(4) << "chi2 " << statistic << ", " << dof << " dof, p " << pValue
    << "; pdf integrates to " << pdfIntegral << ", " << 100.0 * rejected << " % of samples rejected";
  return s.str();
}

ChiSquareResult chiSquareTest(const std::function<std::optional<Vec3>()>& sample,
                              const std::function<double(const Vec3&)>& pdf, const ChiSquareSettings& st) {
  const int nt = st.thetaBins, np = st.phiBins, cells = nt * np;
  std::vector<double> observed(static_cast<size_t>(cells) + 1, 0.0), expected(observed.size(), 0.0);
  const double dTheta = kPiD / nt, dPhi = 2.0 * kPiD / np;
  // Observed: histogram of the samples; the last cell holds the rejected ones.
  for (int i = 0; i < st.samples; ++i) {
    const std::optional<Vec3> w = sample();
    if (!w || !isFinite(*w)) {
      observed.back() += 1.0;
      continue;
    }
    const glm::dvec3 d = glm::normalize(glm::dvec3(*w));
    const double theta = std::acos(std::clamp(d.z, -1.0, 1.0));
    double phi = std::atan2(d.y, d.x);
    if (phi < 0.0) phi += 2.0 * kPiD;
    const int t = std::clamp(static_cast<int>(theta / dTheta), 0, nt - 1);
    const int p = std::clamp(static_cast<int>(phi / dPhi), 0, np - 1);
    observed[static_cast<size_t>(t * np + p)] += 1.0;
  }
  // Expected: N times the pdf integrated over each cell, by adaptive Simpson in theta of adaptive Simpson in
  // phi (sharp lobes of low roughness need the refinement). The ends sit a hair inside the cell: a density
  // that jumps on a cell border (0 below the horizon) is integrated from its own side.
  const double inset = 1e-7;
  const double eps = st.tolerance;
  double integral = 0.0;
  for (int t = 0; t < nt; ++t)
    for (int p = 0; p < np; ++p) {
      const double phi0 = (p + inset) * dPhi, phi1 = (p + 1 - inset) * dPhi;
      const auto overPhi = [&](double theta) {
        const double sinTheta = std::sin(theta), cosTheta = std::cos(theta);
        return sinTheta * adaptiveSimpson(
                              [&](double phi) {
                                const Vec3 w(static_cast<float>(sinTheta * std::cos(phi)),
                                             static_cast<float>(sinTheta * std::sin(phi)), static_cast<float>(cosTheta));
                                const double f = pdf(w);
                                return std::isfinite(f) ? f : 0.0;
                              },
                              phi0, phi1, eps, st.maxDepth);
      };
      const double cell = adaptiveSimpson(overPhi, (t + inset) * dTheta, (t + 1 - inset) * dTheta, eps, st.maxDepth);
      expected[static_cast<size_t>(t * np + p)] = cell * st.samples;
      integral += cell;
    }
  expected.back() = std::max(0.0, 1.0 - integral) * st.samples;
  // Pool the cells expected to hold fewer than 5 samples (smallest first) into one.
  std::vector<size_t> order(expected.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });
  ChiSquareResult r;
  double pooledObserved = 0.0, pooledExpected = 0.0;
  int kept = 0;
  for (size_t i : order) {
    if (expected[i] == 0.0 && observed[i] > 0.0) {  // a sample where the pdf claims none: fail outright
      r.statistic = std::numeric_limits<double>::infinity();
      continue;
    }
    if (expected[i] < 5.0 || pooledExpected < 5.0) {
      pooledObserved += observed[i];
      pooledExpected += expected[i];
      continue;
    }
    const double diff = observed[i] - expected[i];
    r.statistic += diff * diff / expected[i];
    ++kept;
  }
  if (pooledExpected > 0.0) {
    const double diff = pooledObserved - pooledExpected;
    r.statistic += diff * diff / pooledExpected;
    ++kept;
  }
  r.dof = kept - 1;
  r.pValue = std::isfinite(r.statistic) ? chiSquareSurvival(r.statistic, r.dof) : 0.0;
  r.passed = r.pValue >= st.significance;
  r.pdfIntegral = integral;
  r.rejected = observed.back() / st.samples;
  return r;
}

}  // namespace ll
