// Does a sampling routine draw directions with the density it claims?
// Pearson's chi-square goodness-of-fit test over the sphere of directions,
// as pbrt (v3, src/tests/bsdfs.cpp) and Mitsuba 3 test their BSDFs: bin N
// samples into theta x phi cells, integrate the claimed pdf over each cell
// (adaptive Simpson in theta and phi, weight sin theta), pool cells expected to
// hold fewer than 5 samples, and compare. Samples the routine rejects
// (returns nothing) have their own cell, expected N (1 - integral of pdf).
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "core/math.h"

namespace ll {

// P(X >= x) for X chi-square distributed with `dof` degrees of freedom: the
// regularised upper incomplete gamma function Q(dof / 2, x / 2).
double chiSquareSurvival(double x, int dof);

struct ChiSquareResult {
  double statistic = 0.0;
  int dof = 0;
  double pValue = 1.0;
  bool passed = true;      // pValue >= significance
  double pdfIntegral = 0;  // the claimed pdf integrated over the sphere (<= 1)
  double rejected = 0;     // fraction of the samples the routine rejected
  std::string summary() const;  // "chi2 123.4, 87 dof, p 0.31; pdf integrates to 0.9987, 1.2 % rejected"
};

struct ChiSquareSettings {
  int samples = 200000;
  int thetaBins = 10;   // over [0, pi]
  int phiBins = 20;     // over [0, 2 pi)
  double tolerance = 1e-6;  // absolute accuracy of each cell's integral of the pdf (and of each inner one)
  int maxDepth = 10;        // adaptive Simpson's deepest refinement, per cell and dimension
  double significance = 0.01;
};

// sample(): one direction (a unit vector) or nullopt for a rejected sample.
// pdf(w): the density sample() claims for w, per steradian.
ChiSquareResult chiSquareTest(const std::function<std::optional<Vec3>()>& sample,
                              const std::function<double(const Vec3&)>& pdf, const ChiSquareSettings& settings);

}  // namespace ll
