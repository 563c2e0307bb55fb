// The sweep KD-tree build (framework code; the default): Wald and Havran,
// "On building fast kd-trees for ray tracing, and on doing that in
// O(N log N)", IEEE Symposium on Interactive Ray Tracing 2006.
//
// Every face of every primitive's box is a candidate plane. Each node keeps,
// per axis, its boxes' faces as events sorted by position (an end before a
// planar box before a start at one position), sorted once at the root. One
// sweep per axis then counts the boxes below and above every candidate and
// prices it by the surface area heuristic in O(1). Splitting a node keeps
// the order: the events of boxes on one side are filtered into that child in
// sequence; only the straddling triangles, clipped to each child's cell
// ("perfect splits"), get new events, sorted on their own and merged in. So
// every node costs O(n) and the tree O(n log n), with no sorting below the
// root but of the straddlers.
//
// The recursion (termination rules, parallel subtrees, statistics) and the
// clipping are the binned build's (kdtree_top_down.h,
// kdtree_build_support.h). Two things differ: the candidates, and where a
// box lying in the plane goes: to the cheaper side (Wald and Havran's
// p_side), where the binned build always sends it above. Large nodes also
// sweep their three axes, and filter their three event lists, in parallel.
#include <algorithm>
#include <array>
#include <bit>
#include <vector>

#include <tbb/parallel_invoke.h>

#include "core/huge_pages.h"
#include "kdtree.h"
#include "kdtree_build_support.h"
#include "kdtree_top_down.h"

namespace ll::a4::kdbuild {

namespace {

// An event, 8 bytes ordered as one integer: the position's bits made
// sortable (high 32 bits), the kind (2 bits), the primitive's index among the
// node's (30 bits). Positions compare as floats do (-0 is stored as +0).
using Event = uint64_t;
enum EventKind : uint32_t { kEnd = 0, kPlanar = 1, kStart = 2 };
constexpr uint32_t kIndexBits = 30;
constexpr uint32_t kIndexMask = (1u << kIndexBits) - 1u;

uint32_t sortableBits(float x) {
  const uint32_t u = std::bit_cast<uint32_t>(x + 0.0f);  // -0 + 0 = +0
  return (u & 0x80000000u) != 0 ? ~u : u | 0x80000000u;
}
float positionOf(uint32_t key) { return std::bit_cast<float>((key & 0x80000000u) != 0 ? key & 0x7FFFFFFFu : ~key); }
Event makeEvent(float position, EventKind kind, uint32_t index) {
  return (static_cast<uint64_t>(sortableBits(position)) << 32) | (static_cast<uint64_t>(kind) << kIndexBits) | index;
}
uint32_t positionKey(Event e) { return static_cast<uint32_t>(e >> 32); }
uint32_t kindOf(Event e) { return static_cast<uint32_t>(e >> kIndexBits) & 3u; }
uint32_t indexOf(Event e) { return static_cast<uint32_t>(e) & kIndexMask; }
Event withIndex(Event e, uint32_t index) { return (e & ~static_cast<uint64_t>(kIndexMask)) | index; }

using EventLists = std::array<std::vector<Event>, 3>;  // by axis

// floor(x) in [0, bins], clamped as a float before the conversion: x is beyond int's range for far
// boxes, and NaN (0 * infinity) in a cell thinner than float resolution; NaN gives 0.
int binIndex(float x, int bins) {
  return x > 0.0f ? static_cast<int>(std::min(x, static_cast<float>(bins))) : 0;
}

void addEvents(const Bounds3& b, uint32_t index, EventLists& events) {
  for (int a = 0; a < 3; ++a) {
    auto& list = events[static_cast<size_t>(a)];
    if (b.min[a] == b.max[a]) {
      list.push_back(makeEvent(b.min[a], kPlanar, index));
    } else {
      list.push_back(makeEvent(b.min[a], kStart, index));
      list.push_back(makeEvent(b.max[a], kEnd, index));
    }
  }
}

// Sorts events by position and kind (the high 34 bits; the index order of
// equal keys does not matter): three passes of an LSD radix sort.
void radixSort(std::vector<Event>& events, std::vector<Event>& scratch) {
  resizeOnHugePages(scratch, events.size());
  constexpr std::array<uint32_t, 3> kShift{30, 41, 52}, kBits{11, 11, 12};
  std::vector<uint32_t> count;
  for (size_t pass = 0; pass < 3; ++pass) {
    const uint32_t shift = kShift[pass], mask = (1u << kBits[pass]) - 1u;
    count.assign(size_t{mask} + 2, 0u);
    for (const Event e : events) ++count[((e >> shift) & mask) + 1];
    for (size_t d = 1; d < count.size(); ++d) count[d] += count[d - 1];
    for (const Event e : events) scratch[count[(e >> shift) & mask]++] = e;
    events.swap(scratch);
  }
}

// One node's input: its primitives (boxes clipped to its cell) and their events.
struct NodeData {
  std::vector<KdPrim> prims;
  EventLists events;
  void clear() {
    prims.clear();
    for (auto& e : events) e.clear();
  }
};

class Builder : public TopDownBuilder<Builder, NodeData> {
 public:
  explicit Builder(BuildShared& shared) : TopDownBuilder(shared) {}

 private:
  friend class TopDownBuilder<Builder, NodeData>;  // calls prims(), bestPlane() and split()

  static const std::vector<KdPrim>& prims(const NodeData& in) { return in.prims; }

  // The cheapest candidate over the three axes. emptyOnly: only planes with
  // no primitive on one side, priced without the empty bonus (the true SAH
  // cost, to compare with a leaf's).
  KdPlane bestPlane(const NodeData& in, const Bounds3& cell, bool emptyOnly) const {
    std::array<KdPlane, 3> best;
    if (in.prims.size() >= kParallelPrimitives)
      tbb::parallel_invoke([&] { best[0] = bestPlane(in, cell, emptyOnly, 0, kInfinity); },
                           [&] { best[1] = bestPlane(in, cell, emptyOnly, 1, kInfinity); },
                           [&] { best[2] = bestPlane(in, cell, emptyOnly, 2, kInfinity); });
    else
      for (int a = 0; a < 3; ++a)
        best[static_cast<size_t>(a)] = bestPlane(in, cell, emptyOnly, a, a == 0 ? kInfinity : std::min(best[0].cost, best[1].cost));
    // The cheapest; on a tie the lowest axis.
    KdPlane cheapest;
    for (const KdPlane& p : best)
      if (p.cost < cheapest.cost) cheapest = p;
    return cheapest;
  }

  // The cheapest candidate on axis a; one costing more than `beaten` (the best on other axes) may be
  // missed (then a plane costing more is returned).
  KdPlane bestPlane(const NodeData& in, const Bounds3& cell, bool emptyOnly, int a, float beaten) const {
    KdPlane best;
    const float emptySideFactor = emptyOnly ? 1.0f : 1.0f - s_.emptyBonus;
    const auto n = static_cast<uint32_t>(in.prims.size());
    const float invArea = 1.0f / halfArea(cell);
    const Vec3 extent = cell.max - cell.min;
    {
      const float lo = cell.min[a], hi = cell.max[a];
      if (!(hi > lo)) return best;
      // The cell's half area is e1 e2 + length (e1 + e2) for the other axes' extents e1, e2.
      const float e1 = extent[(a + 1) % 3], e2 = extent[(a + 2) % 3];
      const float cap = e1 * e2, rim = e1 + e2;
      // Below a candidate: boxes starting below it; above: boxes ending above it or lying in it.
      uint32_t nBelow = 0, nAbove = n;
      const auto consider = [&](float position, uint32_t nB, uint32_t nA, bool planarBelow) {
        const bool oneSided = nB == 0 || nA == 0;
        if (emptyOnly && !oneSided) return;
        const float areaBelow = cap + (position - lo) * rim, areaAbove = cap + (hi - position) * rim;
        const float cost = s_.traversalCost + (oneSided ? emptySideFactor : 1.0f) * s_.intersectionCost * invArea *
                                                  (areaBelow * static_cast<float>(nB) + areaAbove * static_cast<float>(nA));
        if (cost < best.cost) best = {a, position, cost, planarBelow};
      };
      // Between two event positions the counts are constant and the cost is linear: its minimum is at an
      // event, unless it falls on the cell's face (no plane there). The gaps also offer the binned
      // build's planes (bin boundaries), so the sweep's choice is never worse than the binned build's at
      // a node, and breaks its ties the same way (a flat gap's lowest plane, not a box's face, which
      // keeps trees as cheap overall). Linear: only the first and last boundary in a gap can be its
      // cheapest, so this costs O(1) per gap. A gap reaching the cell's face offers its middle too (the
      // Cornell box's walls all lie in its faces: the middle of the box separates them).
      const int bins = sh_.bins;
      const float binsPerLength = static_cast<float>(bins) / (hi - lo);
      const float* fraction = sh_.binFractions.data();  // b / bins
      const auto boundary = [&](int b) { return lo + (hi - lo) * fraction[b]; };
      const auto considerGap = [&](float from, float to) {
        from = std::max(from, lo);
        to = std::min(to, hi);
        if (!(from < to) || (emptyOnly && nBelow != 0 && nAbove != 0)) return;
        // Most gaps cannot win: the cost is linear across a gap, so the cheaper of its ends (priced with
        // the gap's counts) bounds every plane inside. The slack covers rounding.
        const float oneSidedFactor = nBelow == 0 || nAbove == 0 ? emptySideFactor : 1.0f;
        const float nB = static_cast<float>(nBelow), nA = static_cast<float>(nAbove);
        const float atFrom = cap * (nB + nA) + rim * ((from - lo) * nB + (hi - from) * nA);
        const float atTo = cap * (nB + nA) + rim * ((to - lo) * nB + (hi - to) * nA);
        const float floor = s_.traversalCost + oneSidedFactor * s_.intersectionCost * invArea * std::min(atFrom, atTo);
        if (floor > 1.0001f * std::min(best.cost, beaten)) return;
        int first = binIndex((from - lo) * binsPerLength, bins) + 1;
        while (first > 1 && boundary(first - 1) > from) --first;
        while (first < bins && !(boundary(first) > from)) ++first;
        int last = binIndex((to - lo) * binsPerLength, bins);
        while (last < bins - 1 && boundary(last + 1) < to) ++last;
        while (last > 0 && !(boundary(last) < to)) --last;
        if (first < bins && last > 0 && first <= last) {
          consider(boundary(first), nBelow, nAbove, false);
          if (last != first) consider(boundary(last), nBelow, nAbove, false);
        }
        const float middle = 0.5f * (from + to);
        if ((from == lo || to == hi) && middle > lo && middle < hi) consider(middle, nBelow, nAbove, false);
      };
      const std::vector<Event>& events = in.events[static_cast<size_t>(a)];
      float previous = -kInfinity;
      for (size_t i = 0; i < events.size();) {
        const uint32_t key = positionKey(events[i]);
        const float position = positionOf(key);
        considerGap(previous, position);
        uint32_t count[3] = {0, 0, 0};
        for (; i < events.size() && positionKey(events[i]) == key; ++i) ++count[kindOf(events[i])];
        nAbove -= count[kEnd];
        if (position > lo && position < hi) {
          // Boxes lying in the plane go to the cheaper side (Wald and Havran's p_side).
          const uint32_t planar = count[kPlanar];
          consider(position, nBelow, nAbove, false);
          if (planar > 0) consider(position, nBelow + planar, nAbove - planar, true);
        }
        nBelow += count[kStart] + count[kPlanar];
        nAbove -= count[kPlanar];
        previous = position;
      }
      considerGap(previous, kInfinity);
    }
    return best;
  }

  // Splits `in` at the plane into `below` and `above`: boxes starting below
  // go below, boxes ending above go above, boxes lying in the plane to the
  // side plane.planarBelow says (either holds them: cells are closed);
  // straddling triangles are clipped to each cell.
  void split(const NodeData& in, const KdPlane& plane, const Bounds3& cellBelow, const Bounds3& cellAbove,
             NodeData& below, NodeData& above) {
    const int a = plane.axis;
    const float position = plane.position;
    const bool planarBelow = plane.planarBelow;
    below.clear();
    above.clear();
    const size_t n = in.prims.size();
    dest_.resize(n);
    for (auto& side : straddlers_)
      for (auto& list : side) list.clear();
    for (size_t i = 0; i < n; ++i) {
      const KdPrim& p = in.prims[i];
      const bool inPlane = p.box.min[a] == position && p.box.max[a] == position;
      const bool toBelow = p.box.min[a] < position || (inPlane && planarBelow);
      const bool toAbove = p.box.max[a] > position || (inPlane && !planarBelow);
      if (toBelow && toAbove) {
        dest_[i] = kStraddles;
        Bounds3 b = p.box, t = p.box;
        if (p.prim < sh_.triangleCount) {
          const LeafTriangle& tri = sh_.triangles[p.prim];
          b = clippedBox(p, tri.p0, tri.p1, tri.p2, cellBelow, sh_.pad);
          t = clippedBox(p, tri.p0, tri.p1, tri.p2, cellAbove, sh_.pad);
        } else {  // another kind of primitive: its box cut at the plane
          b.max[a] = position;
          t.min[a] = position;
        }
        if (!b.empty()) addStraddler(below, {b, p.prim}, straddlers_[0]);
        if (!t.empty()) addStraddler(above, {t, p.prim}, straddlers_[1]);
      } else {
        NodeData& to = toBelow ? below : above;
        dest_[i] = static_cast<uint32_t>(to.prims.size()) | (toBelow ? 0u : kAbove);
        to.prims.push_back(p);
      }
    }
    // Events of one-sided boxes keep their order (indices renumbered in order); the straddlers' are merged
    // in. The three axes are independent: a big node filters them in parallel.
    const auto filterAxis = [&](size_t k) {
      std::vector<Event>& to0 = below.events[k];
      std::vector<Event>& to1 = above.events[k];
      reserveOnHugePages(to0, 2 * below.prims.size());
      reserveOnHugePages(to1, 2 * above.prims.size());
      for (const Event e : in.events[k]) {
        const uint32_t d = dest_[indexOf(e)];
        if (d == kStraddles) continue;
        ((d & kAbove) == 0 ? to0 : to1).push_back(withIndex(e, d & kIndexMask));
      }
      mergeStraddlers(to0, straddlers_[0][k], merged_[k]);
      mergeStraddlers(to1, straddlers_[1][k], merged_[k]);
    };
    if (n >= kParallelPrimitives)
      tbb::parallel_invoke([&] { filterAxis(0); }, [&] { filterAxis(1); }, [&] { filterAxis(2); });
    else
      for (size_t k = 0; k < 3; ++k) filterAxis(k);
  }

  static void addStraddler(NodeData& to, const KdPrim& p, EventLists& events) {
    addEvents(p.box, static_cast<uint32_t>(to.prims.size()), events);
    to.prims.push_back(p);
  }

  static void mergeStraddlers(std::vector<Event>& events, std::vector<Event>& added, std::vector<Event>& merged) {
    if (added.empty()) return;
    if (added.size() <= 16) {  // the common case deep in the tree: insertion sort beats std::sort's set-up
      for (size_t i = 1; i < added.size(); ++i) {
        const Event e = added[i];
        size_t j = i;
        for (; j > 0 && added[j - 1] > e; --j) added[j] = added[j - 1];
        added[j] = e;
      }
    } else {
      std::sort(added.begin(), added.end());
    }
    merged.resize(events.size() + added.size());
    std::merge(events.begin(), events.end(), added.begin(), added.end(), merged.begin());
    events.swap(merged);
  }

  // split(): where each primitive goes: its index in the child, kAbove set for the child above; or kStraddles.
  std::vector<uint32_t> dest_;
  static constexpr uint32_t kAbove = 1u << 31, kStraddles = ~0u;
  std::array<EventLists, 2> straddlers_;  // split(): new events of clipped boxes, below and above
  EventLists merged_;                     // split(): scratch of the merges, by axis
};

}  // namespace

BuildTotals buildSweep(KdTree& tree, std::vector<KdPrim> prims, const KdSettings& s, int maxDepth, float pad) {
  BuildShared shared(tree, s, maxDepth, pad);
  Builder builder(shared);
  NodeData& root = builder.input(0);
  const auto n = static_cast<uint32_t>(prims.size());
  for (auto& list : root.events) reserveOnHugePages(list, 2 * size_t{n});
  for (uint32_t i = 0; i < n; ++i) addEvents(prims[i].box, i, root.events);
  root.prims = std::move(prims);
  {
    std::array<std::vector<Event>, 3> scratch;
    tbb::parallel_invoke([&] { radixSort(root.events[0], scratch[0]); },
                         [&] { radixSort(root.events[1], scratch[1]); },
                         [&] { radixSort(root.events[2], scratch[2]); });
  }
  builder.build(root, tree.bounds, 0, 0, 0);
  return builder.takeTree()->writeTree(tree);
}

}  // namespace ll::a4::kdbuild
