// Accelerator `bvh4` (see wide_bvh.h): the binned SAH build collapsed into
// 4-wide nodes, the SSE traversal, and the registration.
#include "accel/wide_bvh.h"

#include <emmintrin.h>  // SSE2 (x86-64 baseline): float -> int conversion of bin indices
#include <xmmintrin.h>  // SSE: the four-box slab test

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "core/huge_pages.h"
#include "core/timer.h"

namespace ll {

namespace {

// --- Build ----------------------------------------------------------------------------

constexpr int kMaxBins = 64;
constexpr uint32_t kParallelPrims = 4096;  // ranges at least this big build their children in parallel
// SAH cost of visiting a 4-wide node, in packet tests (four primitives tested at once, packetsFor()).
constexpr float kNodeCost = 1.0f;
// Beyond this many binary splits every split halves its range, so no path gets deeper than kWideBvhMaxDepth.
constexpr int kForcedHalvingDepth = kWideBvhMaxDepth - 32;

// What n primitives in a leaf cost to test, in packet tests: four are tested at once, so a leaf of 1 to 4
// costs one test. The SAH counts in these units (as Embree's builder counts its leaves in blocks of its
// packet size): counted per primitive, it split leaves the packets would test at once anyway -- twice
// the nodes, half-empty packets, 8-22 % slower queries on the Cornell bunny's path rays.
inline float packetsFor(uint32_t n) { return static_cast<float>((n + 3) / 4); }

__m128 xyzMask() { return _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0)); }

// An axis-aligned box in two SSE registers (world space; lane 3 unused, kept finite).
struct Box {
  __m128 lo = _mm_set1_ps(kInfinity);
  __m128 hi = _mm_set1_ps(-kInfinity);
  void extend(__m128 pLo, __m128 pHi) {
    lo = _mm_min_ps(lo, pLo);
    hi = _mm_max_ps(hi, pHi);
  }
  void extend(const Box& b) { extend(b.lo, b.hi); }
  // ex ey + ey ez + ez ex (what the SAH compares); 0 for an empty box.
  float halfArea() const {
    alignas(16) float e[4];
    _mm_store_ps(e, _mm_max_ps(_mm_sub_ps(hi, lo), _mm_setzero_ps()));  // (a NaN extent counts as 0)
    return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
  }
  Bounds3 bounds3() const {
    alignas(16) float l[4], h[4];
    _mm_store_ps(l, lo);
    _mm_store_ps(h, hi);
    Bounds3 b;
    b.min = Vec3(l[0], l[1], l[2]);
    b.max = Vec3(h[0], h[1], h[2]);
    return b;
  }
};

// One primitive as the build sees it: its box, 32 bytes (the primitive id in lane 3 of lo).
struct PrimRef {
  __m128 lo, hi;
  PrimRef() = default;
  PrimRef(const Bounds3& b, uint32_t prim)
      : lo(_mm_setr_ps(b.min.x, b.min.y, b.min.z, std::bit_cast<float>(prim))),
        hi(_mm_setr_ps(b.max.x, b.max.y, b.max.z, 0.0f)) {}
  __m128 min() const { return _mm_and_ps(lo, xyzMask()); }  // lane 3 zeroed: never a denormal in arithmetic
  __m128 centroid2() const { return _mm_add_ps(min(), hi); }  // twice the box centre
  uint32_t prim() const {
    alignas(16) float v[4];
    _mm_store_ps(v, lo);
    return std::bit_cast<uint32_t>(v[3]);
  }
};

// Maps a doubled centroid to its bin on each axis: floor((c - origin) * scale), clamped to [0, bins).
struct Binning {
  __m128 origin = _mm_setzero_ps();
  __m128 scale = _mm_setzero_ps();  // 0 on an axis without extent: everything in bin 0, axis skipped
  __m128 lastBin = _mm_setzero_ps();
  int bins = 1;
  Binning() = default;
  Binning(const Box& centroids, int binCount)
      : origin(centroids.lo), lastBin(_mm_set1_ps(float(binCount - 1))), bins(binCount) {
    alignas(16) float e[4], s[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    _mm_store_ps(e, _mm_sub_ps(centroids.hi, centroids.lo));
    for (int a = 0; a < 3; ++a)
      if (e[a] > 0.0f && e[a] < kInfinity) s[a] = static_cast<float>(binCount) / e[a];
    scale = _mm_load_ps(s);
  }
  // Bin per axis in lanes 0-2. _mm_max_ps(x, 0) returns 0 for a NaN x, so the conversion is always defined.
  void binsOf(__m128 centroid2, int out[4]) const {
    const __m128 f = _mm_mul_ps(_mm_sub_ps(centroid2, origin), scale);
    const __m128i i = _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(f, _mm_setzero_ps()), lastBin));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out), i);
  }
  bool scaled(int axis) const {
    alignas(16) float s[4];
    _mm_store_ps(s, scale);
    return s[axis] > 0.0f;
  }
};

// Where a range splits: bins [0, boundary) of `axis` go left. axis < 0: no plane separates the range.
struct Split {
  Binning binning;
  int axis = -1;
  int boundary = 0;
  float cost = kInfinity;  // sum over both sides of half area * primitives
};

// Primitives [begin, end) of the build array, with their boxes' and centroids' bounds.
struct Range {
  uint32_t begin = 0, end = 0;
  Box bounds, centroids;  // centroids doubled (lo + hi)
  int depth = 0;          // binary splits above this range
  Split split;
  bool splits = false;       // must or should be a node of its own (true), else a leaf
  bool splitsFreely = false;  // worth splitting where a node has a free child slot
  uint32_t count() const { return end - begin; }
};

class Builder {
 public:
  Builder(PrimRef* prims, uint32_t n, const WideBvhSettings& s)
      : prims_(prims), settings_(s), nodes_(std::make_unique_for_overwrite<WideBvhNode[]>(std::max(n, 1u))) {
    adviseHugePages(nodes_.get(), std::max(n, 1u) * sizeof(WideBvhNode));
  }

  // The range [begin, end) with its bounds computed, depth `depth`, planned.
  Range makeRange(uint32_t begin, uint32_t end, int depth) const {
    Range r;
    r.begin = begin;
    r.end = end;
    r.depth = depth;
    for (uint32_t i = begin; i < end; ++i) {
      r.bounds.extend(prims_[i].min(), prims_[i].hi);
      const __m128 c = prims_[i].centroid2();
      r.centroids.extend(c, c);
    }
    plan(r);
    return r;
  }

  // Builds the 4-wide node over `r` and its subtree; returns its index in the (unordered) node array.
  uint32_t buildNode(const Range& r) {
    Range children[4] = {r};
    int n = 1;
    while (n < 4) {  // split the largest child that wants splitting (the binary tree's grandchildren, pulled up)
      // Children that would otherwise be nodes of their own first, then those a free slot pays for.
      int best = -1;
      float bestArea = 0.0f;
      for (int pass = 0; pass < 2 && best < 0; ++pass)
        for (int i = 0; i < n; ++i) {
          const float area = children[i].bounds.halfArea();
          if ((pass == 0 ? children[i].splits : children[i].splitsFreely) && (best < 0 || area > bestArea)) {
            best = i;
            bestArea = area;
          }
        }
      if (best < 0) break;
      auto [left, right] = split(children[best]);
      for (int i = n; i > best + 1; --i) children[i] = children[i - 1];
      children[best] = left;
      children[best + 1] = right;
      ++n;
    }
    const uint32_t index = next_.fetch_add(1, std::memory_order_relaxed);
    WideBvhNode& node = nodes_[index];
    for (int i = 0; i < 4; ++i) {
      alignas(16) float lo[4] = {kInfinity, kInfinity, kInfinity, 0.0f};
      alignas(16) float hi[4] = {-kInfinity, -kInfinity, -kInfinity, 0.0f};
      node.child[i] = WideBvhNode::kEmpty;
      node.count[i] = 0;
      if (i < n) {
        _mm_store_ps(lo, children[i].bounds.lo);
        _mm_store_ps(hi, children[i].bounds.hi);
        node.child[i] = children[i].begin;
        if (!children[i].splits) node.count[i] = children[i].count();
      }
      for (int a = 0; a < 3; ++a) {
        node.box[0][a][i] = lo[a];
        node.box[1][a][i] = hi[a];
      }
    }
    auto buildChild = [&](int i) { node.child[i] = buildNode(children[i]); };
    if (r.count() >= kParallelPrims) {
      tbb::task_group group;
      for (int i = 0; i < n; ++i)
        if (children[i].splits) group.run([&buildChild, i] { buildChild(i); });
      group.wait();
    } else {
      for (int i = 0; i < n; ++i)
        if (children[i].splits) buildChild(i);
    }
    return index;
  }

  const WideBvhNode* nodes() const { return nodes_.get(); }
  uint32_t nodeCount() const { return next_.load(); }

 private:
  // Decides whether `r` becomes an interior node and, if so, where it splits best.
  void plan(Range& r) const {
    const uint32_t n = r.count();
    const auto maxLeaf = static_cast<uint32_t>(settings_.maxLeaf);
    r.splits = n > maxLeaf;
    if (n < 2 || r.depth >= kForcedHalvingDepth) return;  // (then: halving, see split())
    r.split = bestSplit(r);
    if (r.split.axis < 0) return;
    // Small enough for a leaf: split only where the SAH (in packet tests) says it pays --
    // in a free child slot of the node being built at no traversal cost, else as a node of its own.
    const float area = r.bounds.halfArea();
    r.splitsFreely = r.splits || (area > 0.0f && r.split.cost / area < packetsFor(n));
    if (r.splits) return;
    r.splits = area > 0.0f && kNodeCost + r.split.cost / area < packetsFor(n);
  }

  // Binned SAH over all three axes, one pass over the primitives.
  Split bestSplit(const Range& r) const {
    const uint32_t n = r.count();
    // Small ranges need fewer bins: n primitives fill at most n of them.
    const int fill = static_cast<int>(std::min<uint32_t>(n, kMaxBins)) + 2;
    const int bins = std::clamp(std::min(settings_.bins, fill), 2, kMaxBins);
    Split s;
    s.binning = Binning(r.centroids, bins);
    // Per axis and bin: box corners and primitive count (only bins [0, bins) are initialised and used).
    __m128 binLo[3][kMaxBins], binHi[3][kMaxBins];
    uint32_t count[3][kMaxBins];
    for (int a = 0; a < 3; ++a)
      for (int i = 0; i < bins; ++i) {
        binLo[a][i] = _mm_set1_ps(kInfinity);
        binHi[a][i] = _mm_set1_ps(-kInfinity);
        count[a][i] = 0;
      }
    for (uint32_t i = r.begin; i < r.end; ++i) {
      const PrimRef& p = prims_[i];
      const __m128 lo = p.min();
      alignas(16) int bin[4];
      s.binning.binsOf(p.centroid2(), bin);
      for (int a = 0; a < 3; ++a) {
        binLo[a][bin[a]] = _mm_min_ps(binLo[a][bin[a]], lo);
        binHi[a][bin[a]] = _mm_max_ps(binHi[a][bin[a]], p.hi);
        ++count[a][bin[a]];
      }
    }
    for (int a = 0; a < 3; ++a) {
      if (!s.binning.scaled(a)) continue;
      float rightArea[kMaxBins];
      uint32_t rightCount[kMaxBins];
      Box acc;
      uint32_t m = 0;
      for (int i = bins - 1; i > 0; --i) {  // bins [i, bins)
        acc.extend(binLo[a][i], binHi[a][i]);
        m += count[a][i];
        rightArea[i] = acc.halfArea();
        rightCount[i] = m;
      }
      acc = Box{};
      m = 0;
      for (int i = 1; i < bins; ++i) {  // bins [0, i)
        acc.extend(binLo[a][i - 1], binHi[a][i - 1]);
        m += count[a][i - 1];
        if (m == 0 || rightCount[i] == 0) continue;
        const float cost = acc.halfArea() * packetsFor(m) + rightArea[i] * packetsFor(rightCount[i]);
        if (cost < s.cost) {
          s.cost = cost;
          s.axis = a;
          s.boundary = i;
        }
      }
    }
    return s;
  }

  // Splits `r` in two (its planned SAH split, else in halves along the widest centroid axis); plans both.
  std::pair<Range, Range> split(const Range& r) {
    if (r.split.axis >= 0) {
      Range left, right;
      left.begin = r.begin;
      right.end = r.end;
      left.depth = right.depth = r.depth + 1;
      const Split& s = r.split;
      uint32_t i = r.begin, j = r.end;
      auto goesLeft = [&s](const PrimRef& p) {
        alignas(16) int bin[4];
        s.binning.binsOf(p.centroid2(), bin);
        return bin[s.axis] < s.boundary;
      };
      auto add = [](Range& side, const PrimRef& p) {
        side.bounds.extend(p.min(), p.hi);
        const __m128 c = p.centroid2();
        side.centroids.extend(c, c);
      };
      for (;;) {  // two-sided partition, collecting both sides' bounds on the way
        while (i < j && goesLeft(prims_[i])) add(left, prims_[i++]);
        while (i < j && !goesLeft(prims_[j - 1])) add(right, prims_[--j]);
        if (i >= j) break;
        std::swap(prims_[i], prims_[j - 1]);
      }
      left.end = right.begin = i;
      if (i > r.begin && i < r.end) {  // (always: the SAH split has primitives on both sides)
        plan(left);
        plan(right);
        return {left, right};
      }
    }
    // Identical centroids, or too deep: halves along the widest centroid axis.
    alignas(16) float e[4];
    _mm_store_ps(e, _mm_sub_ps(r.centroids.hi, r.centroids.lo));
    const int axis = e[0] > e[1] ? (e[0] > e[2] ? 0 : 2) : (e[1] > e[2] ? 1 : 2);
    const uint32_t mid = r.begin + r.count() / 2;
    if (e[axis] > 0.0f) {
      std::nth_element(prims_ + r.begin, prims_ + mid, prims_ + r.end, [axis](const PrimRef& a, const PrimRef& b) {
        alignas(16) float ca[4], cb[4];
        _mm_store_ps(ca, a.centroid2());
        _mm_store_ps(cb, b.centroid2());
        return ca[axis] < cb[axis];
      });
    }
    return {makeRange(r.begin, mid, r.depth + 1), makeRange(mid, r.end, r.depth + 1)};
  }

  PrimRef* prims_;
  WideBvhSettings settings_;
  std::unique_ptr<WideBvhNode[]> nodes_;  // at most max(n, 1) nodes: every node but the root splits at least once
  std::atomic<uint32_t> next_{0};
};

// Packs the leaf's primitives prims[begin, begin + count) into packets at the end of out.packets; returns
// the first one's index.
uint32_t packLeaf(const PrimRef* prims, uint32_t begin, uint32_t count, const Geometry& geometry, WideBvh& out) {
  const auto first = static_cast<uint32_t>(out.packets.size());
  for (uint32_t base = 0; base < count; base += 4) {
    WideBvhPacket& packet = out.packets.emplace_back();
    for (int lane = 0; lane < 4; ++lane) {
      const uint32_t prim = base + lane < count ? prims[begin + base + lane].prim() : WideBvhPacket::kEmpty;
      packet.prim[lane] = prim;
      // A triangle with collinear vertices (never hit) is stored as all 0 too: intersectTriangles4()'s precondition.
      Vec3 p[3] = {Vec3(0.0f), Vec3(0.0f), Vec3(0.0f)};
      if (prim < out.triangleCount) {
        for (int k = 0; k < 3; ++k) p[k] = geometry.positions[geometry.triangles[prim][k]];
        if (glm::cross(p[1] - p[0], p[2] - p[0]) == Vec3(0.0f)) p[0] = p[1] = p[2] = Vec3(0.0f);
      }
      for (int k = 0; k < 3; ++k)
        for (int a = 0; a < 3; ++a) packet.triangles.v[k][a][lane] = p[k][a];
    }
  }
  return first;
}

// Copies the subtree of tmp[index] into `out` in depth-first order, leaves packed; returns its new index.
// Accumulates depth and SAH cost (areas relative to the root's).
uint32_t flatten(const WideBvhNode* tmp, uint32_t index, int depth, float rootArea, const PrimRef* prims,
                 const Geometry& geometry, WideBvh& out) {
  const auto at = static_cast<uint32_t>(out.nodes.size());
  out.nodes.push_back(tmp[index]);  // (reserved: no reallocation)
  const WideBvhNode& node = tmp[index];
  Bounds3 all;
  for (int i = 0; i < 4; ++i) {
    if (!node.used(i)) continue;
    const Bounds3 b = node.childBounds(i);
    all.extend(b);
    if (node.isLeaf(i)) {
      out.depth = std::max(out.depth, depth + 1);
      if (rootArea > 0.0f) out.sahCost += double(b.halfSurfaceArea() / rootArea) * double(packetsFor(node.count[i]));
      out.nodes[at].child[i] = packLeaf(prims, node.child[i], node.count[i], geometry, out);
    } else {
      out.nodes[at].child[i] = flatten(tmp, node.child[i], depth + 1, rootArea, prims, geometry, out);
    }
  }
  if (rootArea > 0.0f) out.sahCost += double(all.halfSurfaceArea() / rootArea);
  return at;
}

// --- Traversal ------------------------------------------------------------------------

// Rounding margins of the slab test (Ize, "Robust BVH Ray Traversal", JCGT 2(2), 2013). A plane
// distance (p - o) * (1/d) is within gamma(3) of the exact one, relative; Ize scales the far end of the
// interval by 1 + 2 gamma(3). Here the far planes use 1/d pre-scaled by kFarScale = 1 + 16 u (u = 2^-24,
// the unit roundoff), which also covers the rounding of that product: (1 + 3u) / (1 - 4u) < kFarScale.
constexpr float kFarScale = 1.0f + 16.0f * (std::numeric_limits<float>::epsilon() * 0.5f);
// Absolute slack, in ulps of the distances in the scene (see WideRay::tSlack).
constexpr float kSlackUlps = 32.0f;
constexpr int kStackSize = 3 * kWideBvhMaxDepth + 1;  // each level leaves at most three siblings behind

// Per-ray constants, computed once per query.
struct WideRay {
  Ray ray;
  WatertightRay wray;
  __m128 ox, oy, oz;        // origin, broadcast
  __m128 ix, iy, iz;        // 1/dir, broadcast (near planes); +-infinity for zero components
  __m128 fx, fy, fz;        // 1/dir * kFarScale (far planes)
  __m128 tmin;              // ray.tmin, broadcast
  WatertightRay4 wray4;     // wray on four lanes
  __m128 slack;             // tSlack, broadcast
  int sideX, sideY, sideZ;  // box side of the slab's near plane: 1 (max) where dir < 0 (or -0)
  // The triangle test's t and a box's plane distances round differently, by up to a few ulps of the
  // distances from the origin to the geometry (not of t): a box is skipped only when it lies clearly
  // outside [tmin, tLimit], by tSlack. As in assignments/a4_acceleration/bvh_ray_tests.h, there with
  // |o - c| and 1/|dir|; here with their upper bounds |o - c|_1 and 1/max|dir_i| = |wray.sz|.
  float tSlack;
  WideRay(const Ray& r, const WideBvh& bvh) : ray(r), wray(r), wray4(wray, r.tmin) {
    const __m128 inv = _mm_div_ps(_mm_set1_ps(1.0f), _mm_setr_ps(r.dir.x, r.dir.y, r.dir.z, 1.0f));
    alignas(16) float i[4], f[4];
    _mm_store_ps(i, inv);
    _mm_store_ps(f, _mm_mul_ps(inv, _mm_set1_ps(kFarScale)));
    ox = _mm_set1_ps(r.origin.x);
    oy = _mm_set1_ps(r.origin.y);
    oz = _mm_set1_ps(r.origin.z);
    ix = _mm_set1_ps(i[0]);
    iy = _mm_set1_ps(i[1]);
    iz = _mm_set1_ps(i[2]);
    fx = _mm_set1_ps(f[0]);
    fy = _mm_set1_ps(f[1]);
    fz = _mm_set1_ps(f[2]);
    sideX = i[0] < 0.0f;
    sideY = i[1] < 0.0f;
    sideZ = i[2] < 0.0f;
    const Vec3 oc = glm::abs(r.origin - bvh.sceneCentre);
    tSlack = kSlackUlps * std::numeric_limits<float>::epsilon() * (oc.x + oc.y + oc.z + bvh.sceneRadius) *
             std::abs(wray.sz);
    tmin = _mm_set1_ps(r.tmin);
    slack = _mm_set1_ps(tSlack);
  }
  // Postponed children entered beyond this cannot hold a hit at distance t.
  float cullLimit(float t) const { return t + tSlack; }
  // The far end of the slab test's interval for the closest hit so far at t (margins as for far planes).
  __m128 farLimit(float t) const { return _mm_set1_ps(cullLimit(t) * kFarScale); }
};

// The children of `node` whose boxes the ray meets within [ray.tmin, tLimit], up to rounding (a bit
// mask), and where it enters each (tEntry). It is a4's rayEntersBox, tn <= tf * (1 + 2 gamma(3)) +
// tSlack, on four boxes at once, rearranged to tn - tSlack <= tf' with the far planes pre-scaled
// (shorter dependency chain). tLimit: farLimit(hit.t). Axis-parallel rays are exact: a plane distance
// 0 * inf is NaN, and _mm_max_ps(a, b) / _mm_min_ps(a, b) return b when a is NaN, so the interval stays
// as it was -- the closed slab contains the ray. Unused slots (empty boxes) are never entered.
inline int enterChildren(const WideRay& r, const WideBvhNode& node, __m128 tLimit, __m128& tEntry) {
  const __m128 nx = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(node.box[r.sideX][0]), r.ox), r.ix);
  const __m128 ny = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(node.box[r.sideY][1]), r.oy), r.iy);
  const __m128 nz = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(node.box[r.sideZ][2]), r.oz), r.iz);
  const __m128 fx = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(node.box[1 - r.sideX][0]), r.ox), r.fx);
  const __m128 fy = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(node.box[1 - r.sideY][1]), r.oy), r.fy);
  const __m128 fz = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(node.box[1 - r.sideZ][2]), r.oz), r.fz);
  __m128 tn = _mm_max_ps(nx, r.tmin);  // (operand order matters: NaN first)
  tn = _mm_max_ps(ny, tn);
  tn = _mm_max_ps(nz, tn);
  __m128 tf = _mm_min_ps(fx, tLimit);
  tf = _mm_min_ps(fy, tf);
  tf = _mm_min_ps(fz, tf);
  tEntry = tn;
  return _mm_movemask_ps(_mm_cmple_ps(_mm_sub_ps(tn, r.slack), tf));
}

// The next float above t (t finite or infinite, not NaN).
inline float nextFloatUp(float t) {
  if (t == kInfinity) return t;
  if (t == 0.0f) return std::numeric_limits<float>::denorm_min();
  const uint32_t bits = std::bit_cast<uint32_t>(t);
  return std::bit_cast<float>(t > 0.0f ? bits + 1 : bits - 1);
}

// The lanes of a leaf's packet `base / 4` that hold one of its `count` primitives.
inline unsigned usedLanes(uint32_t count, uint32_t base) { return count - base >= 4 ? 0xfu : (1u << (count - base)) - 1u; }

// Brute force's rule for primitive `prim`: it replaces `hit` when its t is below this bound -- a smaller
// t, or on equal t a smaller primitive id than a hit already found.
inline float closerBound(uint32_t prim, const Hit& hit) {
  return (hit.prim != Hit::kNone && prim < hit.prim) ? nextFloatUp(hit.t) : hit.t;
}

// Tests lane `lane` of `packet` with the scalar tests and keeps in `hit` what brute force keeps: the
// smallest t in (ray.tmin, ray.tmax), on equal t the smaller primitive id. Returns whether `hit` changed.
inline bool closerHit(const WideBvh& bvh, const WideBvhPacket& packet, int lane, const WideRay& r, Hit& hit) {
  const uint32_t prim = packet.prim[lane];
  const float tmax = closerBound(prim, hit);
  float t, b1 = 0.0f, b2 = 0.0f;
  if (prim < bvh.triangleCount) {
    if (!intersectTriangle(r.wray, packet.vertex(0, lane), packet.vertex(1, lane), packet.vertex(2, lane),
                           r.ray.tmin, tmax, t, b1, b2))
      return false;
  } else {
    const Sphere& s = bvh.geometry->spheres[prim - bvh.triangleCount];
    if (!intersectSphere(r.ray, s.center, s.radius, r.ray.tmin, tmax, t)) return false;
  }
  hit.t = t;
  hit.prim = prim;
  hit.b1 = b1;
  hit.b2 = b2;
  return true;
}

// Whether lane `lane` of `packet` is hit with ray.tmin < t < ray.tmax.
inline bool anyHit(const WideBvh& bvh, const WideBvhPacket& packet, int lane, const WideRay& r) {
  const uint32_t prim = packet.prim[lane];
  float t, b1, b2;
  if (prim < bvh.triangleCount) {
    return intersectTriangle(r.wray, packet.vertex(0, lane), packet.vertex(1, lane), packet.vertex(2, lane),
                             r.ray.tmin, r.ray.tmax, t, b1, b2);
  }
  const Sphere& s = bvh.geometry->spheres[prim - bvh.triangleCount];
  return intersectSphere(r.ray, s.center, s.radius, r.ray.tmin, r.ray.tmax, t);
}

// A postponed child: a node (count == 0) or a leaf's `count` primitives in packets from `ref`.
struct StackEntry {
  uint32_t ref;
  uint32_t count;
  float tEntry;  // where the ray enters its box
};

// Depth first, nearest child first. AnyHit: return at the first primitive hit. hit.t starts at ray.tmax.
template <bool AnyHit>
bool traverse(const WideBvh& bvh, const WideRay& r, Hit& hit, QueryCounters& counters) {
  const WideBvhNode* nodes = bvh.nodes.data();
  StackEntry stack[kStackSize];
  int sp = 0;
  uint32_t ref = 0, count = 0;  // the root
  float tLimit = r.cullLimit(hit.t);
  __m128 tLimit4 = r.farLimit(hit.t);
  uint64_t nodesSeen = 0, primsSeen = 0;
  bool anything = false;  // a hit found
  for (;;) {
    if (count == 0) {
      ++nodesSeen;
      const WideBvhNode& node = nodes[ref];
      __m128 tEntry;
      unsigned mask = static_cast<unsigned>(enterChildren(r, node, tLimit4, tEntry));
      if (mask != 0) {
        alignas(16) float t[4], tKey[4];
        _mm_store_ps(t, tEntry);
        _mm_store_ps(tKey, _mm_max_ps(tEntry, _mm_setzero_ps()));  // (>= 0: ordered as their bits)
        // Start loading every child entered: their cache misses overlap instead of following one another.
        for (unsigned m = mask; m != 0; m &= m - 1) {
          const int c = std::countr_zero(m);
          const char* p = node.count[c] == 0 ? reinterpret_cast<const char*>(&nodes[node.child[c]])
                                             : reinterpret_cast<const char*>(&bvh.packets[node.child[c]]);
          _mm_prefetch(p, _MM_HINT_T0);
          _mm_prefetch(p + 64, _MM_HINT_T0);
          if (node.count[c] != 0) _mm_prefetch(p + 128, _MM_HINT_T0);  // (a packet's third line)
        }
        if ((mask & (mask - 1)) == 0) {  // one child: no stack
          const int a = std::countr_zero(mask);
          ref = node.child[a];
          count = node.count[a];
          continue;
        }
        // Two to four: sort by decreasing entry distance without branches (keys: the bits of the distance
        // clamped to >= 0, then the slot), push all but the nearest, take the nearest. Any hit: no order.
        uint64_t key[4];
        int k = 0;
        for (unsigned m = mask; m != 0; m &= m - 1) {
          const auto c = static_cast<unsigned>(std::countr_zero(m));
          key[k++] = (uint64_t{std::bit_cast<uint32_t>(tKey[c])} << 32) | c;
        }
        auto order = [&key](int i, int j) {  // key[i] >= key[j] afterwards
          const uint64_t lo = std::min(key[i], key[j]), hi = std::max(key[i], key[j]);
          key[i] = hi;
          key[j] = lo;
        };
        if constexpr (AnyHit) {
        } else if (k == 2) {
          order(0, 1);
        } else if (k == 3) {
          order(0, 1);
          order(1, 2);
          order(0, 1);
        } else {
          order(0, 1);
          order(2, 3);
          order(0, 2);
          order(1, 3);
          order(1, 2);
        }
        for (int i = 0; i < k - 1; ++i) {
          const auto c = static_cast<int>(key[i] & 3u);
          stack[sp++] = {node.child[c], node.count[c], t[c]};
        }
        const auto c = static_cast<int>(key[k - 1] & 3u);
        ref = node.child[c];
        count = node.count[c];
        continue;
      }
    } else {
      primsSeen += count;
      const WideBvhPacket* packet = &bvh.packets[ref];
      for (uint32_t base = 0; base < count && !(AnyHit && anything); base += 4, ++packet) {
        // Closest hit: lanes up to one float beyond hit.t (the tie rule's bound) stay candidates.
        const __m128 tmax = _mm_set1_ps(AnyHit ? r.ray.tmax : nextFloatUp(hit.t));
        TriangleHits4 found;
        intersectTriangles4(r.wray4, packet->triangles, tmax, found);
        const unsigned used = usedLanes(count, base);
        bool closer = false;
        if constexpr (AnyHit) {
          anything = (found.hit & used) != 0;
        } else {
          for (unsigned m = found.hit & used; m != 0; m &= m - 1) {
            const int lane = std::countr_zero(m);
            const uint32_t prim = packet->prim[lane];
            if (found.t[lane] < closerBound(prim, hit)) {
              hit.t = found.t[lane];
              hit.prim = prim;
              hit.b1 = found.b1[lane];
              hit.b2 = found.b2[lane];
              closer = true;
            }
          }
        }
        for (unsigned m = found.undecided & used; m != 0 && !(AnyHit && anything); m &= m - 1) {
          const int lane = std::countr_zero(m);
          if constexpr (AnyHit) {
            anything = anyHit(bvh, *packet, lane, r);
          } else {
            closer |= closerHit(bvh, *packet, lane, r, hit);
          }
        }
        if (!AnyHit && closer) {
          anything = true;
          tLimit = r.cullLimit(hit.t);
          tLimit4 = r.farLimit(hit.t);
        }
      }
      if (AnyHit && anything) break;
    }
    // Resume at the nearest postponed child that may still hold a closer hit; none left: done.
    bool resumed = false;
    while (sp > 0 && !resumed) {
      const StackEntry& e = stack[--sp];
      resumed = e.tEntry <= tLimit;
      ref = e.ref;
      count = e.count;
    }
    if (!resumed) break;
  }
  counters.add({nodesSeen, primsSeen});
  return anything;
}

// --- The accelerator ------------------------------------------------------------------

class WideBvhAccelerator final : public Accelerator {
 public:
  explicit WideBvhAccelerator(const WideBvhSettings& settings) : settings_(settings) {}

  void build(const Geometry& geometry) override {
    const Timer timer;
    bvh_ = buildWideBvh(geometry, settings_);
    buildSeconds_ = timer.seconds();
  }

  bool intersect(const Ray& ray, Hit& hit, QueryCounters& counters) const override {
    return intersectWideBvh(bvh_, ray, hit, counters);
  }

  bool occluded(const Ray& ray, QueryCounters& counters) const override {
    return occludedWideBvh(bvh_, ray, counters);
  }

  AcceleratorStats stats() const override {
    AcceleratorStats s;
    s.buildSeconds = buildSeconds_;
    s.memoryBytes = bvh_.memoryBytes();
    s.nodeCount = bvh_.nodes.size();
    s.depth = bvh_.depth;
    s.sahCost = bvh_.sahCost;
    return s;
  }

  // The 4-wide nodes at `depth` (their box: the union of their children's) and the leaves above.
  std::vector<NodeShape> nodesAtDepth(int depth) const override {
    std::vector<NodeShape> shapes;
    if (bvh_.nodes.empty()) return shapes;
    std::vector<std::pair<uint32_t, int>> stack{{0u, 0}};  // (node, its depth)
    while (!stack.empty()) {
      const auto [index, d] = stack.back();
      stack.pop_back();
      const WideBvhNode& n = bvh_.nodes[index];
      if (d == depth) {
        NodeShape shape;
        for (int i = 0; i < 4; ++i)
          if (n.used(i)) shape.box.extend(n.childBounds(i));
        shapes.push_back(shape);
        continue;
      }
      for (int i = 3; i >= 0; --i) {
        if (!n.used(i)) continue;
        if (n.isLeaf(i)) {
          NodeShape shape;
          shape.box = n.childBounds(i);
          shape.leaf = true;
          shapes.push_back(shape);
        } else {
          stack.emplace_back(n.child[i], d + 1);
        }
      }
    }
    return shapes;
  }

 private:
  WideBvhSettings settings_;
  WideBvh bvh_;
  double buildSeconds_ = 0.0;
};

}  // namespace

WideBvh buildWideBvh(const Geometry& geometry, const WideBvhSettings& settings) {
  WideBvh bvh;
  bvh.geometry = &geometry;
  bvh.triangleCount = geometry.triangleCount();
  const uint32_t n = geometry.primitiveCount();
  if (n == 0) return bvh;
  auto prims = std::make_unique_for_overwrite<PrimRef[]>(n);
  adviseHugePages(prims.get(), n * sizeof(PrimRef));
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, n, 4096), [&](const tbb::blocked_range<uint32_t>& range) {
    for (uint32_t p = range.begin(); p < range.end(); ++p) prims[p] = PrimRef(geometry.bounds(p), p);
  });
  Builder builder(prims.get(), n, settings);
  const Range root = builder.makeRange(0, n, 0);
  const uint32_t rootIndex = builder.buildNode(root);

  const Bounds3 sceneBox = root.bounds.bounds3();
  bvh.sceneCentre = sceneBox.center();
  bvh.sceneRadius = 0.5f * sceneBox.diagonal();
  reserveOnHugePages(bvh.nodes, builder.nodeCount());  // exactly: flatten() never reallocates
  reserveOnHugePages(bvh.packets, n);                   // at most one packet per primitive
  flatten(builder.nodes(), rootIndex, 0, sceneBox.halfSurfaceArea(), prims.get(), geometry, bvh);
  bvh.packets.shrink_to_fit();
  if (!(sceneBox.halfSurfaceArea() > 0.0f)) bvh.sahCost = static_cast<double>(n);
  return bvh;
}

bool intersectWideBvh(const WideBvh& bvh, const Ray& ray, Hit& hit, QueryCounters& counters) {
  hit = Hit{};
  hit.t = ray.tmax;
  if (bvh.nodes.empty()) return false;
  return traverse<false>(bvh, WideRay(ray, bvh), hit, counters);
}

bool occludedWideBvh(const WideBvh& bvh, const Ray& ray, QueryCounters& counters) {
  if (bvh.nodes.empty()) return false;
  Hit hit;
  hit.t = ray.tmax;
  return traverse<true>(bvh, WideRay(ray, bvh), hit, counters);
}

AcceleratorInfo wideBvhAccelerator() {
  return {"bvh4",
          "4-wide bounding volume hierarchy with SSE traversal: the framework's fast path (binned SAH build "
          "collapsed to four children per node, nearest child first); `bvh` stays assignment 4's binary structure",
          {ParamDecl::integer("max_leaf", 4, 1, 16, "most primitives in one leaf"),
           ParamDecl::integer("bins", 16, 2, kMaxBins, "SAH bins per axis")},
          [](const ParamSet& p) -> std::unique_ptr<Accelerator> {
            WideBvhSettings s;
            s.maxLeaf = p.getInt("max_leaf");
            s.bins = p.getInt("bins");
            return std::make_unique<WideBvhAccelerator>(s);
          }};
}

}  // namespace ll
