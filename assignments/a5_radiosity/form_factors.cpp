#include "form_factors.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "a5_tasks.h"
#include "core/rng.h"
#include "core/spherical_triangle.h"
#include "render/ray_offset.h"
#include "render/student_task.h"

namespace ll::a5 {

namespace {

using Entry = FormFactorEntry;

// Orthonormal tangents (t, b) of unit n.
void tangentFrame(const Vec3& n, Vec3& t, Vec3& b) {
  t = glm::normalize(std::abs(n.x) > 0.5f ? glm::cross(n, Vec3(0, 1, 0)) : glm::cross(n, Vec3(1, 0, 0)));
  b = glm::cross(n, t);
}

// The hemicube's cells: unit directions in the local frame (z = normal) and
// delta form factors. Top face z = 1, res x res cells over [-1, 1]^2:
// dF = dA / (pi (x^2 + y^2 + 1)^2). Side faces (x or y = +-1, z in [0, 1],
// res x res/2 cells): dF = z dA / (pi (u^2 + z^2 + 1)^2), u the in-face coordinate.
struct HemicubeCell {
  Vec3 dir;
  float dF;
};
std::vector<HemicubeCell> hemicube(int res) {
  std::vector<HemicubeCell> cells;
  const float step = 2.0f / static_cast<float>(res), dA = step * step;
  for (int j = 0; j < res; ++j)
    for (int i = 0; i < res; ++i) {
      const float x = -1.0f + (static_cast<float>(i) + 0.5f) * step, y = -1.0f + (static_cast<float>(j) + 0.5f) * step;
      const float r2 = x * x + y * y + 1.0f;
      cells.push_back({glm::normalize(Vec3(x, y, 1.0f)), dA / (kPi * r2 * r2)});
    }
  const int half = std::max(res / 2, 1);
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < half; ++k)
      for (int i = 0; i < res; ++i) {
        const float u = -1.0f + (static_cast<float>(i) + 0.5f) * step;
        const float z = (static_cast<float>(k) + 0.5f) / static_cast<float>(half);
        const float dAside = step * (1.0f / static_cast<float>(half));
        const float r2 = u * u + z * z + 1.0f;
        Vec3 d = side == 0 ? Vec3(1, u, z) : side == 1 ? Vec3(-1, u, z) : side == 2 ? Vec3(u, 1, z) : Vec3(u, -1, z);
        cells.push_back({glm::normalize(d), z * dAside / (kPi * r2 * r2)});
      }
  // The midpoint rule's weights sum to 1 + 0.54 / res^2, not 1: a closed
  // room's rows would sum to more than 1 and bias B by rho 0.54 / (res^2
  // (1 - rho)) (5 % at rho = 0.99, res = 32). Normalised, they sum to 1.
  double total = 0.0;
  for (const HemicubeCell& c : cells) total += static_cast<double>(c.dF);
  for (HemicubeCell& c : cells) c.dF = static_cast<float>(static_cast<double>(c.dF) / total);
  return cells;
}

// The hemicube's turn about patch i's normal (radians), random per patch:
// axis-aligned hemicubes over axis-aligned geometry put their rows of cell
// rays at the same places against every patch's edges, and the errors add
// up (two parallel unit squares 2 apart as 1024 triangles: F -0.15 %);
// turned at random, they average out (within 0.1 %).
float hemicubeTurn(uint64_t seed, uint32_t i) { return 2.0f * kPi * Rng(seed ^ 0x6e6d63756265ull, i).uniform(); }

// Clips convex polygon `in` (count <= 4) to the half-space n.(v - x) >= 0 (x's
// front side); writes at most kClipCapacity corners to `out` and returns
// their count (0 if it would need more). A corner within 1e-5 of the
// polygon's size of the plane counts as on it: a polygon lying in x's plane
// (a coplanar neighbour) has distances that are rounding noise, and
// alternating noise signs would cross the plane at every edge. Consecutive
// duplicate corners are dropped: the contour integral of A5.1 needs no edge
// of zero length.
constexpr int kClipCapacity = 8;
int clipAbove(const Vec3& x, const Vec3& n, const Vec3* in, int count, Vec3* out) {
  float size = 0.0f;
  for (int k = 1; k < count; ++k) size = std::max(size, glm::length(in[k] - in[0]));
  const float onPlane = 1e-5f * size;
  float d[4];
  for (int k = 0; k < count; ++k) {
    d[k] = glm::dot(n, in[k] - x);
    if (std::abs(d[k]) <= onPlane) d[k] = 0.0f;
  }
  int m = 0;
  const auto emit = [&](const Vec3& v) {
    if (m > 0 && v == out[m - 1]) return true;
    if (m == kClipCapacity) return false;
    out[m++] = v;
    return true;
  };
  for (int k = 0; k < count; ++k) {
    const int next = (k + 1) % count;
    if (d[k] >= 0.0f && !emit(in[k])) return 0;
    if ((d[k] > 0.0f && d[next] < 0.0f) || (d[k] < 0.0f && d[next] > 0.0f))
      if (!emit(in[k] + (d[k] / (d[k] - d[next])) * (in[next] - in[k]))) return 0;
  }
  if (m > 1 && out[m - 1] == out[0]) --m;
  return m;
}

std::vector<Entry> analyticRow(const PatchMesh& mesh, const Accelerator& accel, uint32_t i, int visSamples,
                               QueryCounters& q, uint64_t& rays) {
  const Patch& pi = mesh.patches[i];
  std::vector<Entry> row;
  for (uint32_t j = 0; j < mesh.patches.size(); ++j) {
    if (j == i) continue;
    const Patch& pj = mesh.patches[j];
    if (glm::dot(pj.normal, pi.centre - pj.centre) <= 0.0f) continue;  // i is behind j's front side
    Vec3 poly[4];
    const int corners = mesh.cornerPositions(j, poly);
    Vec3 clipped[kClipCapacity];
    const int n = clipAbove(pi.centre, pi.normal, poly, corners, clipped);
    if (n < 3) continue;
    const float f = pointToPolygonFormFactor(pi.centre, pi.normal, clipped, n);
    if (!(f > 0.0f)) continue;
    int seen = 0;
    for (int s = 0; s < visSamples; ++s) {
      // The centre first, then stratified points on j.
      const Vec3 y = s == 0 ? pj.centre
                            : pointOnPolygon(poly, corners,
                                             Vec2(std::fmod(0.618034f * static_cast<float>(s), 1.0f),
                                                  (static_cast<float>(s) + 0.5f) / static_cast<float>(visSamples)));
      seen += visibleBetween(accel, pi.centre, pi.normal, y, pj.normal, q) ? 1 : 0;
      ++rays;
    }
    if (seen > 0) row.push_back({j, f * static_cast<float>(seen) / static_cast<float>(visSamples)});
  }
  return row;
}

// Cells [begin, end) of patch i's hemicube: the patch each cell's ray hits
// in front (hitPatch[c]; Hit::kNone for nothing, patch i or a back side).
void castHemicube(const PatchMesh& mesh, const Accelerator& accel, uint32_t i, const std::vector<HemicubeCell>& cells,
                  uint64_t seed, size_t begin, size_t end, std::vector<uint32_t>& hitPatch, QueryCounters& q) {
  const Patch& p = mesh.patches[i];
  Vec3 t0, b0;
  tangentFrame(p.normal, t0, b0);
  const float turn = hemicubeTurn(seed, i);
  const Vec3 t = std::cos(turn) * t0 + std::sin(turn) * b0, b = glm::cross(p.normal, t);
  Ray r;
  r.origin = offsetRayOrigin(p.centre, p.normal);
  r.tmin = 0.0f;
  for (size_t c = begin; c < end; ++c) {
    r.dir = cells[c].dir.x * t + cells[c].dir.y * b + cells[c].dir.z * p.normal;
    r.tmax = kInfinity;
    Hit hit;
    const uint32_t j = accel.intersect(r, hit, q) ? mesh.primPatch[hit.prim] : Hit::kNone;
    const bool front = j != Hit::kNone && j != i && glm::dot(mesh.patches[j].normal, r.dir) < 0.0f;  // received in front
    hitPatch[c] = front ? j : Hit::kNone;
  }
}

// The row from the cells' hits: each patch's delta form factors summed.
// `accumulator` (size N) is all zero on entry and on return.
std::vector<Entry> sumCells(const std::vector<HemicubeCell>& cells, const std::vector<uint32_t>& hitPatch,
                            std::vector<float>& accumulator) {
  std::vector<uint32_t> seen;
  for (size_t c = 0; c < cells.size(); ++c) {
    const uint32_t j = hitPatch[c];
    if (j == Hit::kNone) continue;
    if (accumulator[j] == 0.0f) seen.push_back(j);
    accumulator[j] += cells[c].dF;
  }
  std::sort(seen.begin(), seen.end());
  std::vector<Entry> row;
  row.reserve(seen.size());
  for (const uint32_t j : seen) {
    row.push_back({j, accumulator[j]});
    accumulator[j] = 0.0f;
  }
  return row;
}

std::vector<Entry> hemicubeRow(const PatchMesh& mesh, const Accelerator& accel, uint32_t i,
                               const std::vector<HemicubeCell>& cells, uint64_t seed, std::vector<float>& accumulator,
                               QueryCounters& q, uint64_t& rays) {
  std::vector<uint32_t> hitPatch(cells.size());
  castHemicube(mesh, accel, i, cells, seed, 0, cells.size(), hitPatch, q);
  rays += cells.size();
  return sumCells(cells, hitPatch, accumulator);
}

// A direction from x into convex polygon `corners` (3 to kClipCapacity, a
// fan from corner 0), uniform in solid angle; `solidAngle` gets the
// polygon's (0: degenerate).
Vec3 sampleSolidAngle(const Vec3& x, const Vec3* corners, int count, Vec2 u, double& solidAngle) {
  std::optional<SphericalTriangle> fan[kClipCapacity - 2];
  solidAngle = 0.0;
  for (int k = 0; k + 2 < count; ++k) {
    fan[k] = sphericalTriangle(glm::dvec3(x), glm::dvec3(corners[0]), glm::dvec3(corners[k + 1]),
                               glm::dvec3(corners[k + 2]));
    if (fan[k]) solidAngle += fan[k]->solidAngle;
  }
  if (!(solidAngle > 0.0)) return Vec3(0.0f);
  // Triangle k with probability its share; u.x reused within it.
  double ux = static_cast<double>(u.x) * solidAngle;
  int k = 0;
  for (; k + 3 < count; ++k) {
    const double share = fan[k] ? fan[k]->solidAngle : 0.0;
    if (ux < share) break;
    ux -= share;
  }
  if (!fan[k])  // (a degenerate triangle picked by rounding: take the first sound one)
    for (k = 0; !fan[k]; ++k) {
    }
  ux = std::clamp(ux / fan[k]->solidAngle, 0.0, 1.0 - 1e-12);
  return Vec3(sampleSphericalTriangle(*fan[k], glm::dvec2(ux, static_cast<double>(u.y))));
}

// Monte Carlo form factors with finite variance next to a shared edge. The
// point-pair estimator A_j cos cos / (pi r^2) has infinite variance there
// (1/r^2 is not square-integrable along the edge: row sums of 0.73-1.33 in
// a 12-patch cube). Here the inner integral is exact and only visibility is
// sampled: for N stratified points x on i (shared by the row, so a closed,
// empty room's rows sum to exactly 1),
//   F_ij = mean over x of [ F(x -> j) - (Omega / pi) cos_x(w) (1 - V(x, w)) ],
// F(x -> j) the point-to-polygon form factor (A5.1) of j clipped to x's
// front side, w one direction uniform in the solid angle Omega of that
// polygon (Arvo 1995), V whether x sees j along w. The bracket's mean is
// the visible point-to-polygon form factor (control variate: no variance at
// all where nothing is in between); both terms are bounded, so the variance
// is finite. A pair's mean is clamped at 0 (bias only for pairs almost fully
// hidden, where single brackets can be negative).
std::vector<Entry> monteCarloRow(const PatchMesh& mesh, const Accelerator& accel, uint32_t i, int samples,
                                 uint64_t seed, QueryCounters& q, uint64_t& rays) {
  const Patch& pi = mesh.patches[i];
  Vec3 ti[4];
  const int ni = mesh.cornerPositions(i, ti);
  Rng rng(seed, i);
  // Points x on i, jittered on a k x k grid of the unit square (k^2 <= samples; the rest uniform).
  std::vector<Vec3> xs(static_cast<size_t>(samples));
  const int grid = static_cast<int>(std::sqrt(static_cast<double>(samples)));
  for (int s = 0; s < samples; ++s) {
    Vec2 u = rng.uniform2();
    if (s < grid * grid)
      u = (Vec2(static_cast<float>(s % grid), static_cast<float>(s / grid)) + u) / static_cast<float>(grid);
    xs[static_cast<size_t>(s)] = pointOnPolygon(ti, ni, glm::min(u, Vec2(1.0f - 1e-7f)));
  }
  std::vector<Entry> row;
  for (uint32_t j = 0; j < mesh.patches.size(); ++j) {
    if (j == i) continue;
    const Patch& pj = mesh.patches[j];
    Vec3 tj[4];
    const int nj = mesh.cornerPositions(j, tj);
    // No x on i sees j's front: j wholly behind i's plane, or i wholly behind j's.
    const auto behind = [](const Vec3& n, const Vec3& origin, const Vec3* t, int count) {
      for (int k = 0; k < count; ++k)
        if (glm::dot(n, t[k] - origin) > 0.0f) return false;
      return true;
    };
    if (behind(pi.normal, pi.centre, tj, nj) || behind(pj.normal, pj.centre, ti, ni)) continue;
    double sum = 0.0;
    for (int s = 0; s < samples; ++s) {
      const Vec3& x = xs[static_cast<size_t>(s)];
      const Vec2 u = Vec2((static_cast<float>(s) + rng.uniform()) / static_cast<float>(samples), rng.uniform());
      if (glm::dot(pj.normal, x - tj[0]) <= 0.0f) continue;  // x behind j
      Vec3 clipped[kClipCapacity];
      const int n = clipAbove(x, pi.normal, tj, nj, clipped);
      if (n < 3) continue;
      const double f = static_cast<double>(pointToPolygonFormFactor(x, pi.normal, clipped, n));
      if (!(f > 0.0)) continue;
      double omega = 0.0;
      const Vec3 w = sampleSolidAngle(x, clipped, n, u, omega);
      const float cosX = glm::dot(pi.normal, w), along = glm::dot(pj.normal, w);
      sum += f;
      if (!(omega > 0.0) || !(cosX > 0.0f) || !(along < 0.0f)) continue;
      const Vec3 y = x + (glm::dot(pj.normal, tj[0] - x) / along) * w;  // where w meets j's plane
      ++rays;
      if (!visibleBetween(accel, x, pi.normal, y, pj.normal, q))
        sum -= omega / static_cast<double>(kPi) * static_cast<double>(cosX);
    }
    const double f = sum / samples;
    if (f > 0.0) row.push_back({j, static_cast<float>(f)});
  }
  return row;
}

}  // namespace

bool visibleBetween(const Accelerator& accel, const Vec3& x, const Vec3& ni, const Vec3& y, const Vec3& nj,
                    QueryCounters& q) {
  Ray r;
  r.origin = offsetRayOrigin(x, ni);
  const Vec3 target = offsetRayOrigin(y, faceTowards(nj, x - y));
  r.dir = target - r.origin;
  r.tmin = kSegmentTrim;
  r.tmax = 1.0f - kSegmentTrim;
  return !accel.occluded(r, q);
}

struct HemicubeRows::Cells {
  std::vector<HemicubeCell> cells;
};

HemicubeRows::HemicubeRows(const PatchMesh& mesh, const Accelerator& accel, int resolution, uint64_t seed)
    : mesh_(mesh), accel_(accel), cells_(std::make_unique<Cells>()), accumulator_(mesh.patches.size(), 0.0f),
      seed_(seed) {
  cells_->cells = hemicube(std::max(resolution, 2));
}

HemicubeRows::~HemicubeRows() = default;

std::vector<FormFactorEntry> HemicubeRows::row(uint32_t i) {
  // One row's rays in parallel (progressive refinement computes rows one by one).
  const std::vector<HemicubeCell>& cells = cells_->cells;
  std::vector<uint32_t> hitPatch(cells.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, cells.size(), 256), [&](const tbb::blocked_range<size_t>& range) {
    QueryCounters q;
    castHemicube(mesh_, accel_, i, cells, seed_, range.begin(), range.end(), hitPatch, q);
  });
  rays_ += cells.size();
  return sumCells(cells, hitPatch, accumulator_);
}

float FormFactors::at(uint32_t i, uint32_t j) const {
  const auto begin = column.begin() + rowStart[i], end = column.begin() + rowStart[i + 1];
  const auto it = std::lower_bound(begin, end, j);
  return it != end && *it == j ? value[static_cast<size_t>(it - column.begin())] : 0.0f;
}

std::string methodName(FormFactorMethod m) {
  return m == FormFactorMethod::Analytic ? "analytic" : m == FormFactorMethod::Hemicube ? "hemicube" : "montecarlo";
}

FormFactors computeFormFactors(const PatchMesh& mesh, const Accelerator& accel, const FormFactorSettings& s,
                               FormFactorDiagnostics* diagnostics, const std::function<void(size_t, size_t)>& progress) {
  const size_t n = mesh.patches.size();
  std::vector<std::vector<Entry>> rows(n);
  const std::vector<HemicubeCell> cells =
      s.method == FormFactorMethod::Hemicube ? hemicube(std::max(s.hemicubeResolution, 2)) : std::vector<HemicubeCell>{};
  std::atomic<uint64_t> rays{0};
  std::atomic<size_t> done{0};
  TaskLog* log = currentTaskLog();  // where the A5.1 stub reports, on every worker
  // simple_partitioner: ranges of at most 16 rows, so progress (and with it cancellation, a progress
  // report that throws) comes every 16 rows; the auto partitioner hands out ranges of thousands of rows
  // on a big mesh, and a switch away from radiosity on the 235k bunny waited 3.5 s for one to end.
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, static_cast<uint32_t>(n), 16),
                    [&](const tbb::blocked_range<uint32_t>& range) {
                      const ScopedTaskLog scope(log);
                      QueryCounters q;
                      uint64_t local = 0;
                      std::vector<float> accumulator(s.method == FormFactorMethod::Hemicube ? n : 0, 0.0f);
                      for (uint32_t i = range.begin(); i < range.end(); ++i) {
                        switch (s.method) {
                          case FormFactorMethod::Analytic:
                            rows[i] = analyticRow(mesh, accel, i, std::max(s.visibilitySamples, 1), q, local);
                            break;
                          case FormFactorMethod::Hemicube:
                            rows[i] = hemicubeRow(mesh, accel, i, cells, s.seed, accumulator, q, local);
                            break;
                          case FormFactorMethod::MonteCarlo:
                            rows[i] = monteCarloRow(mesh, accel, i, std::max(s.monteCarloSamples, 1), s.seed, q, local);
                            break;
                        }
                      }
                      rays += local;
                      const size_t finished = done += range.size();
                      if (progress) progress(finished, n);
                    },
                    tbb::simple_partitioner());
  FormFactors f;
  f.rowStart.assign(n + 1, 0);
  for (size_t i = 0; i < n; ++i) f.rowStart[i + 1] = f.rowStart[i] + static_cast<uint32_t>(rows[i].size());
  f.column.resize(f.rowStart[n]);
  f.value.resize(f.rowStart[n]);
  for (size_t i = 0; i < n; ++i)
    for (size_t k = 0; k < rows[i].size(); ++k) {
      f.column[f.rowStart[i] + k] = rows[i][k].j;
      f.value[f.rowStart[i] + k] = rows[i][k].f;
    }
  if (diagnostics) {
    FormFactorDiagnostics& d = *diagnostics;
    d = {};
    d.nonZeros = f.column.size();
    d.visibilityRays = rays.load();
    d.rowSumMin = n > 0 ? 1e30 : 0.0;
    double exchanged = 0.0;
    for (uint32_t i = 0; i < n; ++i) {
      double sum = 0.0;
      for (uint32_t k = f.rowStart[i]; k < f.rowStart[i + 1]; ++k) {
        sum += static_cast<double>(f.value[k]);
        const uint32_t j = f.column[k];
        const double aij = static_cast<double>(mesh.patches[i].area) * static_cast<double>(f.value[k]);
        const double aji = static_cast<double>(mesh.patches[j].area) * static_cast<double>(f.at(j, i));
        d.reciprocityMeanError += std::abs(aij - aji);
        exchanged += aij;
        if (std::max(f.value[k], f.at(j, i)) > 1e-2f)
          d.reciprocityMaxError = std::max(d.reciprocityMaxError, std::abs(aij - aji) / std::max(aij, aji));
      }
      d.rowSumMin = std::min(d.rowSumMin, sum);
      d.rowSumMax = std::max(d.rowSumMax, sum);
      d.rowSumMean += sum;
    }
    if (n > 0) d.rowSumMean /= static_cast<double>(n);
    if (exchanged > 0.0) d.reciprocityMeanError /= exchanged;
  }
  return f;
}

double parallelSquaresFormFactor(double a, double h) {
  const double x = a / h, y = a / h;
  const double x2 = x * x, y2 = y * y;
  return 2.0 / (std::numbers::pi * x * y) *
         (std::log(std::sqrt((1 + x2) * (1 + y2) / (1 + x2 + y2))) + x * std::sqrt(1 + y2) * std::atan(x / std::sqrt(1 + y2)) +
          y * std::sqrt(1 + x2) * std::atan(y / std::sqrt(1 + x2)) - x * std::atan(x) - y * std::atan(y));
}

double perpendicularRectanglesFormFactor(double l, double w1, double w2) {
  const double w = w1 / l, h = w2 / l;
  const double w2_ = w * w, h2 = h * h, s = std::sqrt(h2 + w2_);
  const double a = (1 + w2_) * (1 + h2) / (1 + w2_ + h2);
  const double b = std::pow(w2_ * (1 + w2_ + h2) / ((1 + w2_) * (w2_ + h2)), w2_);
  const double c = std::pow(h2 * (1 + h2 + w2_) / ((1 + h2) * (h2 + w2_)), h2);
  return 1.0 / (std::numbers::pi * w) *
         (w * std::atan(1 / w) + h * std::atan(1 / h) - s * std::atan(1 / s) + 0.25 * std::log(a * b * c));
}

}  // namespace ll::a5
