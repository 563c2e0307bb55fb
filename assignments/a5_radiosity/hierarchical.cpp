#include "hierarchical.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numbers>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/rng.h"
#include "form_factors.h"
#include "render/ray_offset.h"

namespace ll::a5 {

namespace {

constexpr uint32_t kNone = ~0u;
// The form-factor quadrature subdivides the receiver where the source is
// closer than twice the sub-triangle's radius, down to this depth (4^depth
// sub-triangles at most, each with the degree-2 rule).
constexpr int kQuadratureDepth = 2;
// After a solve, a link is refined again only when it carries 10 % more than
// the threshold: new B moves links near the threshold back and forth, and
// without the slack rounds would go on refining one link at a time.
constexpr double kRecheckSlack = 1.1;
// Refinement is done when no more than this fraction of the links is above
// the threshold after a solve (the last few take a round each, for nothing
// one can see).
constexpr double kSettled = 1e-3;

struct Tri {
  Vec3 a, b, c;  // counter-clockwise from the front
};

// Child k of the midpoint subdivision (3 is the middle one); same winding as t.
Tri childOf(const Tri& t, int k) {
  const Vec3 ab = 0.5f * (t.a + t.b), bc = 0.5f * (t.b + t.c), ca = 0.5f * (t.c + t.a);
  switch (k) {
    case 0: return {t.a, ab, ca};
    case 1: return {ab, t.b, bc};
    case 2: return {ca, bc, t.c};
    default: return {bc, ca, ab};
  }
}

Vec3 centroid(const Tri& t) { return (t.a + t.b + t.c) / 3.0f; }
float radiusAbout(const Tri& t, const Vec3& c) {
  return std::sqrt(std::max({glm::dot(t.a - c, t.a - c), glm::dot(t.b - c, t.b - c), glm::dot(t.c - c, t.c - c)}));
}

// One node of a base patch's quadtree. Children are 4 consecutive ids, all
// larger than their parent's (created in a serial pass, in id order).
struct Element {
  Tri tri;
  Vec3 centre{0.0f};   // centroid
  float area = 0.0f;   // scene units^2: the base patch's / 4^depth
  float radius = 0.0f; // largest distance from the centre to a corner
  uint32_t base = 0;   // base patch (= the root's id)
  uint32_t parent = kNone, child = kNone;
};

Element makeElement(const Tri& t, float area, uint32_t base, uint32_t parent) {
  Element e;
  e.tri = t;
  e.centre = centroid(t);
  e.area = area;
  e.radius = radiusAbout(t, e.centre);
  e.base = base;
  e.parent = parent;
  return e;
}

enum Decision : uint8_t { kUndecided, kAccept, kSplitSource, kSplitReceiver, kDrop };

// A link (p <- q), stored at the receiver p.
struct Link {
  uint32_t q = 0;
  float f = 0.0f;  // F_pq estimate, unoccluded
  float v = 0.0f;  // fraction of the sample pairs (front to front) that see each other
  uint8_t evaluated = 0;
  uint8_t visible = 0;  // every sample pair saw the other (inherited from the parent link when it did)
  uint8_t decision = kUndecided;
};

// Clips polygon `in` to the half-space n.(v - x) >= eps; returns the new count (<= count + 1).
int clipAbove(const Vec3& x, const Vec3& n, const Vec3* in, int count, Vec3* out, float eps) {
  int m = 0;
  for (int k = 0; k < count; ++k) {
    const Vec3& a = in[k];
    const Vec3& b = in[(k + 1) % count];
    const float da = glm::dot(n, a - x) - eps, db = glm::dot(n, b - x) - eps;
    if (da >= 0.0f) out[m++] = a;
    if ((da >= 0.0f) != (db >= 0.0f)) out[m++] = a + (da / (da - db)) * (b - a);
  }
  return m;
}

// Lambert's contour integral: the form factor from the point x (unit normal
// n) to the polygon, which lies in x's front half-space and does not touch x:
// F = |sum_k beta_k n.(r_k x r_k+1) / |r_k x r_k+1|| / (2 pi), r_k = v_k - x.
double pointToPolygon(const Vec3& x, const Vec3& n, const Vec3* poly, int count) {
  // Single precision: r_k is exact to an ulp of the coordinates, and
  // atan2 of (|c|, a.b) is well conditioned at every angle.
  float sum = 0.0f;
  Vec3 a = poly[0] - x;
  for (int k = 0; k < count; ++k) {
    const Vec3 b = poly[(k + 1) % count] - x;
    const Vec3 c = glm::cross(a, b);
    const float len = glm::length(c);
    if (len > 0.0f) sum += std::atan2(len, glm::dot(a, b)) * glm::dot(n, c) / len;  // (len = 0: x on the edge's line)
    a = b;
  }
  return static_cast<double>(std::abs(sum)) / (2.0 * std::numbers::pi);
}

struct SourceView {
  const Tri* q;  // the source
  Vec3 np, nq;   // unit normals of receiver and source
  Vec3 qCentre;
  float qRadius;
  float eps;  // scene units: what counts as on a plane
};

// F from the point x on the receiver to the source: 0 when x is on or behind the source's plane.
double pointEstimate(const Vec3& x, const SourceView& g) {
  if (glm::dot(g.nq, x - g.q->a) <= g.eps) return 0.0;
  const Vec3 tri[3] = {g.q->a, g.q->b, g.q->c};
  Vec3 clipped[4];
  const int m = clipAbove(x, g.np, tri, 3, clipped, g.eps);
  return m < 3 ? 0.0 : pointToPolygon(x, g.np, clipped, m);
}

// The mean over triangle t of the point form factor: the degree-2 rule (Strang and
// Fix: barycentrics (2/3, 1/6, 1/6) and permutations), on sub-triangles where the source is near.
double triangleEstimate(const Tri& t, const SourceView& g, int depth) {
  const Vec3 c = centroid(t);
  const float r = radiusAbout(t, c);
  if (depth < kQuadratureDepth && glm::length(c - g.qCentre) - g.qRadius < 2.0f * r) {
    double sum = 0.0;
    for (int k = 0; k < 4; ++k) sum += triangleEstimate(childOf(t, k), g, depth + 1);
    return 0.25 * sum;
  }
  constexpr float w1 = 2.0f / 3.0f, w2 = 1.0f / 6.0f;
  return (pointEstimate(w1 * t.a + w2 * t.b + w2 * t.c, g) + pointEstimate(w2 * t.a + w1 * t.b + w2 * t.c, g) +
          pointEstimate(w2 * t.a + w2 * t.b + w1 * t.c, g)) /
         3.0;
}

// A point in stratum `index` of t's midpoint subdivision `levels` deep, u in [0, 1)^2 within it.
Vec3 stratifiedPoint(Tri t, uint32_t index, int levels, Vec2 u) {
  for (int l = 0; l < levels; ++l) t = childOf(t, static_cast<int>((index >> (2 * l)) & 3u));
  const float s = std::sqrt(u.x);
  return (1.0f - s) * t.a + s * (1.0f - u.y) * t.b + s * u.y * t.c;
}

// Whether *some* vertex of `t` lies in front of the plane through `o` with normal n (by more than eps).
bool anyInFront(const Tri& t, const Vec3& o, const Vec3& n, float eps) {
  return glm::dot(n, t.a - o) > eps || glm::dot(n, t.b - o) > eps || glm::dot(n, t.c - o) > eps;
}

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

class HierarchicalSolver {
 public:
  HierarchicalSolver(const PatchMesh& base, const Accelerator& accel, const HierarchicalSettings& s)
      : mesh_(base), accel_(accel), s_(s) {
    double totalArea = 0.0, power = 0.0;
    for (uint32_t i = 0; i < base.patches.size(); ++i) {
      const Patch& p = base.patches[i];
      const Tri t{base.positions[p.vertices.x], base.positions[p.vertices.y], base.positions[p.vertices.z]};
      el_.push_back(makeElement(t, p.area, i, kNone));
      totalArea += static_cast<double>(p.area);
      power += static_cast<double>(p.area) * static_cast<double>(maxComponent(p.emission));
    }
    threshold_ = s.linkEpsilon * power;
    minArea_ = s.minArea * totalArea;
    eps_ = 1e-5f * base.geometry.sceneBounds().diagonal();
    samples_ = std::max(s.visibilitySamples, 1);
    while ((1 << (2 * levels_)) < samples_) ++levels_;
    resize();
    for (uint32_t i = 0; i < el_.size(); ++i) b_[i] = base.patches[i].emission;
    // The first links: every base patch from every other (phase A drops the pairs that do not face).
    for (uint32_t p = 0; p < el_.size(); ++p) {
      if (!(el_[p].area > 0.0f) || maxComponent(mesh_.patches[p].reflectance) <= 0.0f) continue;
      for (uint32_t q = 0; q < el_.size(); ++q)
        if (q != p && el_[q].area > 0.0f) pending_[p].push_back(Link{q});
    }
  }

  HierarchicalResult run(const std::function<void(double)>& progress) {
    const auto start = std::chrono::steady_clock::now();
    const auto report = [&](double fraction) {
      if (progress) progress(fraction);
    };
    bool refined = false, solved = false;
    size_t left = 0;
    for (int round = 0;; ++round) {
      const double r = round;
      report(r / (r + 2.0));
      auto t = std::chrono::steady_clock::now();
      refine();
      result_.refineSeconds += since(t);
      report((r + 0.5) / (r + 2.0));
      t = std::chrono::steady_clock::now();
      solved = solve(s_.tolerance, start);
      result_.solveSeconds += since(t);
      result_.rounds = round + 1;
      if (!result_.failure.empty()) return finish(start);
      t = std::chrono::steady_clock::now();
      left = recheck(false);
      result_.refineSeconds += since(t);
      // (Round 0 refines for the emitted light only: always another round.)
      if (left == 0 || (round > 0 && static_cast<double>(left) <= kSettled * static_cast<double>(linkCount()))) {
        refined = true;
        break;
      }
      if (round + 1 >= s_.maxRounds || capped_) break;
      t = std::chrono::steady_clock::now();
      recheck(true);
      result_.refineSeconds += since(t);
    }
    if (nonFinite_ > 0)
      result_.failure = std::to_string(nonFinite_) + " non-finite form-factor estimates (links dropped)";
    else if (!solved)
      result_.failure = "gather: relative change " +
                        std::to_string(result_.history.empty() ? 0.0 : result_.history.back().residual) + " after " +
                        std::to_string(s_.maxIterations) + " iterations (tolerance " + std::to_string(s_.tolerance) +
                        ")";
    else if (capped_)
      result_.failure = "refinement stopped at the element limit (" + std::to_string(s_.maxElements) + ")";
    else if (!refined)
      result_.failure = "refinement: " + std::to_string(left) + " links still above linkEpsilon after " +
                        std::to_string(s_.maxRounds) + " rounds";
    result_.converged = result_.failure.empty();
    report(1.0);
    return finish(start);
  }

 private:
  void resize() {
    const size_t n = el_.size();
    b_.resize(n, Rgb(0.0f));
    gathered_.resize(n, Rgb(0.0f));
    links_.resize(n);
    pending_.resize(n);
    next_.resize(n);
    splitFlag_.resize(n, 0);
  }

  size_t linkCount() const {
    size_t n = 0;
    for (const std::vector<Link>& l : links_) n += l.size();
    return n;
  }

  bool splittable(uint32_t e) const { return el_[e].area > minArea_ && el_[e].area > 0.0f; }

  // The power (W) the link would carry unoccluded: rho_p A_p F_pq B_q, largest over r, g, b.
  double power(uint32_t p, const Link& l) const {
    return static_cast<double>(el_[p].area * l.f * maxComponent(mesh_.patches[el_[p].base].reflectance * b_[l.q]));
  }

  // F estimate and visibility of link (p <- q); false when it carries nothing (drop it).
  bool evaluate(uint32_t p, Link& l, QueryCounters& counters, uint64_t& rays) {
    l.evaluated = 1;
    const Element& ep = el_[p];
    const Element& eq = el_[l.q];
    const Vec3 np = mesh_.patches[ep.base].normal, nq = mesh_.patches[eq.base].normal;
    if (!anyInFront(eq.tri, ep.centre, np, eps_) || !anyInFront(ep.tri, eq.centre, nq, eps_)) return false;
    const double f = triangleEstimate(ep.tri, SourceView{&eq.tri, np, nq, eq.centre, eq.radius, eps_}, 0);
    if (!std::isfinite(f)) {
      ++nonFinite_;
      return false;
    }
    if (!(f > 0.0)) return false;
    l.f = static_cast<float>(std::min(f, 1.0));
    if (l.visible) {  // the parent link saw all its samples: so do its children
      l.v = 1.0f;
      return true;
    }
    // A link about to be split passes its verdict on to its children when
    // every sample sees: it looks with 4 times the rays.
    const bool splits = power(p, l) > threshold_ && (splittable(p) || splittable(l.q));
    const int samples = splits ? 4 * samples_ : samples_, levels = splits ? levels_ + 1 : levels_;
    // Stratum x of p with stratum (x + offset) of q, points jittered in their strata.
    Rng rng(mix64(s_.seed ^ mix64(p)), l.q);
    const uint32_t strata = 1u << (2 * levels), offset = rng.nextU32() % strata;
    int valid = 0, seen = 0;
    for (int k = 0; k < samples; ++k) {
      const uint32_t ix = static_cast<uint32_t>(static_cast<uint64_t>(k) * strata / static_cast<uint64_t>(samples));
      const Vec3 x = stratifiedPoint(ep.tri, ix, levels, rng.uniform2());
      const Vec3 y = stratifiedPoint(eq.tri, (ix + offset) % strata, levels, rng.uniform2());
      const Vec3 d = y - x;
      if (glm::dot(np, d) <= 0.0f || glm::dot(nq, d) >= 0.0f) continue;  // not front to front
      ++valid;
      ++rays;
      if (visibleBetween(accel_, x, np, y, nq, counters)) ++seen;
    }
    if (valid > 0 && seen == 0) return false;  // blocked everywhere we looked
    l.v = valid > 0 ? static_cast<float>(seen) / static_cast<float>(valid) : 1.0f;
    l.visible = seen == samples ? 1 : 0;
    return true;
  }

  static Link childLink(uint32_t q, const Link& parent) {
    Link l;
    l.q = q;
    l.visible = parent.visible;
    return l;
  }

  void decide(uint32_t p, Link& l) {
    if (power(p, l) <= threshold_) {
      l.decision = kAccept;
      return;
    }
    const bool canP = splittable(p), canQ = splittable(l.q);
    const std::atomic_ref<uint8_t> flagP(splitFlag_[p]), flagQ(splitFlag_[l.q]);
    if (canQ && (el_[l.q].area > el_[p].area || !canP)) {
      l.decision = kSplitSource;
      flagQ.store(1, std::memory_order_relaxed);
    } else if (canP) {
      l.decision = kSplitReceiver;
      flagP.store(1, std::memory_order_relaxed);
    } else {
      l.decision = kAccept;
    }
  }

  // Refinement passes until no link is pending: (A) evaluate and decide every
  // pending link, in parallel; (B) split the marked elements, serially in id
  // order; (C) every element collects its next pending links (those to the
  // children of split sources, and its parent's links split on the receiver
  // side) and keeps the accepted ones, in parallel.
  void refine() {
    std::atomic<uint64_t> rays{0};
    for (;;) {
      size_t n = el_.size();
      tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 64), [&](const tbb::blocked_range<size_t>& range) {
        QueryCounters counters;
        uint64_t local = 0;
        for (size_t p = range.begin(); p < range.end(); ++p)
          for (Link& l : pending_[p]) {
            if (!l.evaluated && !evaluate(static_cast<uint32_t>(p), l, counters, local)) {
              l.decision = kDrop;
              continue;
            }
            decide(static_cast<uint32_t>(p), l);
          }
        rays += local;
      });
      for (uint32_t e = 0; e < n; ++e) {
        if (!splitFlag_[e]) continue;
        splitFlag_[e] = 0;
        if (el_[e].child != kNone) continue;
        if (el_.size() + 4 > s_.maxElements) {
          capped_ = true;
          continue;
        }
        el_[e].child = static_cast<uint32_t>(el_.size());
        const Element parent = el_[e];
        for (int k = 0; k < 4; ++k) el_.push_back(makeElement(childOf(parent.tri, k), 0.25f * parent.area, parent.base, e));
        resize();
        for (int k = 0; k < 4; ++k) b_[parent.child + static_cast<uint32_t>(k)] = b_[e];
      }
      n = el_.size();
      std::atomic<size_t> next{0};
      tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256), [&](const tbb::blocked_range<size_t>& range) {
        size_t local = 0;
        for (size_t e = range.begin(); e < range.end(); ++e) {
          std::vector<Link>& out = next_[e];
          out.clear();
          for (const Link& l : pending_[e]) {
            const bool keep = l.decision == kAccept || (l.decision == kSplitSource && el_[l.q].child == kNone) ||
                              (l.decision == kSplitReceiver && el_[e].child == kNone);
            if (keep) {
              links_[e].push_back(l);
              links_[e].back().decision = kAccept;
            } else if (l.decision == kSplitSource) {
              for (uint32_t k = 0; k < 4; ++k) out.push_back(childLink(el_[l.q].child + k, l));
            }
          }
          if (el_[e].parent != kNone)
            for (const Link& l : pending_[el_[e].parent])
              if (l.decision == kSplitReceiver) out.push_back(childLink(l.q, l));
          local += out.size();
        }
        next += local;
      });
      tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1024), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t e = range.begin(); e < range.end(); ++e) std::swap(pending_[e], next_[e]);
      });
      if (next.load() == 0) break;
    }
    result_.visibilityRays += rays.load();
  }

  // Links that now carry too much (B changed) and can still be refined: moved
  // back to pending when `move`; returns how many.
  size_t recheck(bool move) {
    std::atomic<size_t> count{0};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, el_.size(), 256), [&](const tbb::blocked_range<size_t>& range) {
      size_t local = 0;
      for (size_t p = range.begin(); p < range.end(); ++p) {
        std::vector<Link>& ls = links_[p];
        size_t kept = 0;
        for (size_t k = 0; k < ls.size(); ++k) {
          const Link& l = ls[k];
          const bool again = power(static_cast<uint32_t>(p), l) > kRecheckSlack * threshold_ &&
                             (splittable(static_cast<uint32_t>(p)) || splittable(l.q));
          local += again ? 1 : 0;
          if (again && move) {
            pending_[p].push_back(l);
            pending_[p].back().decision = kUndecided;
          } else {
            ls[kept++] = l;
          }
        }
        ls.resize(kept);
      }
      count += local;
    });
    return count.load();
  }

  // Jacobi gathering over the links plus push-pull until the leaves' B
  // changes by less than `tolerance` (relative); false at the iteration cap.
  bool solve(double tolerance, std::chrono::steady_clock::time_point start) {
    const size_t n = el_.size();
    std::vector<Rgb> down(n);
    for (int it = 0; it < s_.maxIterations; ++it) {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t p = range.begin(); p < range.end(); ++p) {
          Rgb sum(0.0f);
          for (const Link& l : links_[p]) sum += (l.f * l.v) * b_[l.q];
          gathered_[p] = mesh_.patches[el_[p].base].reflectance * sum;
        }
      });
      // Push (parents come before their children) and the leaves' new B, then pull (children first).
      float change = 0.0f, peak = 0.0f;
      for (uint32_t e = 0; e < n; ++e) {
        const Element& x = el_[e];
        if (x.parent == kNone) down[e] = Rgb(0.0f);
        if (x.child != kNone) {
          for (uint32_t k = 0; k < 4; ++k) down[x.child + k] = down[e] + gathered_[e];
          continue;
        }
        const Rgb b = mesh_.patches[x.base].emission + gathered_[e] + down[e];
        if (!isFinite(b)) {
          result_.failure = "non-finite radiosity at element " + std::to_string(e) + " of base patch " +
                            std::to_string(x.base) + " in iteration " + std::to_string(iteration_ + 1);
          return false;
        }
        change = std::max(change, maxComponent(glm::abs(b - b_[e])));
        peak = std::max(peak, maxComponent(b));
        b_[e] = b;
      }
      for (uint32_t e = static_cast<uint32_t>(n); e-- > 0;) {
        const uint32_t c = el_[e].child;
        if (c != kNone) b_[e] = 0.25f * (b_[c] + b_[c + 1] + b_[c + 2] + b_[c + 3]);
      }
      const double residual = peak > 0.0f ? static_cast<double>(change / peak) : 0.0;
      result_.history.push_back({++iteration_, residual, since(start)});
      if (residual < tolerance) return true;
    }
    return false;
  }

  HierarchicalResult finish(std::chrono::steady_clock::time_point start) {
    HierarchicalResult& r = result_;
    const bool failed = !r.converged && r.failure.rfind("non-finite radiosity", 0) == 0;
    r.elements = el_.size();
    r.basePatchRadiosity.assign(mesh_.patches.size(), Rgb(0.0f));
    for (uint32_t e = 0; e < el_.size(); ++e) {
      r.links += links_[e].size();
      if (el_[e].parent == kNone && !failed) r.basePatchRadiosity[e] = b_[e];
      if (el_[e].child != kNone) continue;
      const auto v = static_cast<uint32_t>(r.positions.size());
      r.positions.insert(r.positions.end(), {el_[e].tri.a, el_[e].tri.b, el_[e].tri.c});
      r.triangles.emplace_back(v, v + 1, v + 2);
      r.radiosity.push_back(failed ? Rgb(0.0f) : b_[e]);  // never a NaN in a result
      r.basePatch.push_back(el_[e].base);
    }
    r.leaves = r.triangles.size();
    r.seconds = since(start);
    return std::move(r);
  }

  const PatchMesh& mesh_;
  const Accelerator& accel_;
  const HierarchicalSettings& s_;
  std::vector<Element> el_;
  std::vector<Rgb> b_, gathered_;  // per element: B (leaves) or its area-weighted mean (inner), and rho * gathered
  std::vector<std::vector<Link>> links_, pending_, next_;
  std::vector<uint8_t> splitFlag_;
  double threshold_ = 0.0;  // W: linkEpsilon * emitted power
  float minArea_ = 0.0f;    // scene units^2
  float eps_ = 0.0f;        // scene units
  int samples_ = 1, levels_ = 0;
  int iteration_ = 0;
  bool capped_ = false;
  std::atomic<size_t> nonFinite_{0};
  HierarchicalResult result_;
};

}  // namespace

HierarchicalResult solveHierarchical(const PatchMesh& base, const Accelerator& accel, const HierarchicalSettings& settings,
                                     const std::function<void(double)>& progress) {
  HierarchicalSolver solver(base, accel, settings);
  return solver.run(progress);
}

}  // namespace ll::a5
