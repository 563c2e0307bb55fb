// The top-down recursion both KD-tree builds share (framework code): when a
// node becomes a leaf, the SAH bookkeeping, the progress reports, and the
// parallel subtrees. A build supplies how a node's plane is found and how
// its primitives are split, as `Derived` (CRTP):
//   static const std::vector<KdPrim>& prims(const Input&);  // the node's primitives
//   KdPlane bestPlane(const Input&, const Bounds3& cell, bool emptyOnly) const;
//   void split(Input& in, const KdPlane&, const Bounds3& cellBelow, const Bounds3& cellAbove,
//              Input& below, Input& above);
// emptyOnly: only planes with no primitive on one side, priced without the
// empty bonus (the true SAH cost, to compare with a leaf's).
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <tbb/parallel_invoke.h>

#include "core/phase_progress.h"
#include "kdtree.h"
#include "kdtree_build_support.h"
#include "kdtree_subtree.h"

namespace ll::a4::kdbuild {

// One node's plane: x[axis] = position, its SAH cost.
struct KdPlane {
  int axis = -1;  // -1: no plane found
  float position = 0.0f;
  float cost = kInfinity;
  bool planarBelow = false;  // boxes lying in the plane go below (else above)
};

constexpr int kMaxBins = 64;

// Shared by the builders of one tree (the parallel subtrees'), read-only but the node counter.
struct BuildShared {
  BuildShared(const KdTree& tree, const KdSettings& s, int maxDepthIn, float padIn)
      : settings(s), bins(std::clamp(s.bins, 2, kMaxBins)), maxDepth(maxDepthIn), pad(padIn),
        triangles(tree.triangles), triangleCount(tree.triangleCount), sink(currentPhaseSink()) {
    for (int b = 0; b <= bins; ++b)
      binFractions[static_cast<size_t>(b)] = static_cast<float>(b) / static_cast<float>(bins);
  }

  const KdSettings& settings;
  int bins;      // settings.bins within [2, kMaxBins]
  int maxDepth;  // most splits that leave primitives on both sides
  float pad;     // see clippedBox()
  const std::vector<LeafTriangle>& triangles;  // by primitive id
  uint32_t triangleCount;
  const PhaseSink* sink;  // the calling thread's progress sink (thread-safe), or null
  std::atomic<size_t> nodes{0};
  std::array<float, kMaxBins + 1> binFractions{};  // b / bins for b = 0 .. bins: bin boundaries, no division
};

// Nodes with at least this many primitives build their two subtrees in parallel (and the builds do
// their own work on such nodes in parallel).
constexpr size_t kParallelPrimitives = 8192;

template <class Derived, class Input>
class TopDownBuilder {
 public:
  explicit TopDownBuilder(BuildShared& shared) : sh_(shared), s_(shared.settings), scratch_(kKdMaxDepth + 2) {}

  // The input of a subtree's root at `depth`, to fill before build().
  Input& input(int depth) { return scratch_[static_cast<size_t>(depth)][0]; }

  // Builds the subtree of `cell` over `in` (boxes clipped to the cell). depth:
  // edges from the root; splits: of those, the ones that left primitives on
  // both sides (cutting off empty space does not count against maxDepth, or
  // a small object in a big scene would run out of depth before its
  // primitives are separated).
  void build(Input& in, const Bounds3& cell, int depth, int splits, int badRefines) {
    Derived& self = static_cast<Derived&>(*this);
    const std::vector<KdPrim>& prims = Derived::prims(in);
    const uint32_t index = out_->addNode();
    // Nodes made by every builder of the tree, counted in batches (one shared counter per node would
    // bounce its cache line between the threads); reported, which is also where a GUI pane's newer
    // request cancels the build (its phase report throws).
    if ((++unreported_ & 0x3FFF) == 0 || prims.size() > 50000) {
      const size_t made = sh_.nodes.fetch_add(unreported_, std::memory_order_relaxed) + unreported_;
      unreported_ = 0;
      if (sh_.sink) (*sh_.sink)("kd-tree build (" + std::to_string(made) + " nodes)", -1.0);
    }
    const size_t made = sh_.nodes.load(std::memory_order_relaxed) + out_->nodeCount();
    out_->depth = std::max(out_->depth, depth);
    const size_t n = prims.size();
    const double area = halfArea(cell);
    if (n == 0 || splits >= sh_.maxDepth || depth >= kKdMaxDepth || made + 2 > kKdMaxNodes)
      return makeLeaf(index, prims, area);
    // A node with few primitives is a leaf unless a plane with nothing on one
    // side lowers its SAH cost: so a wall lying in the cell's face gets a
    // thin slab of its own, and rays crossing the rest of the cell skip it.
    const bool few = n <= static_cast<size_t>(s_.maxLeaf);
    const KdPlane plane = self.bestPlane(in, cell, few);
    const float leafCost = s_.intersectionCost * static_cast<float>(n);
    if (plane.axis < 0 || (few && plane.cost >= leafCost)) return makeLeaf(index, prims, area);
    // PBRT allows a few uphill splits to get out of local minima; not below 16 primitives, where they
    // only multiplied nodes (235k bunny: 3.4 M -> 2.0 M nodes, SAH cost within 0.4 %, render time alike).
    if (plane.cost >= leafCost) ++badRefines;
    if ((plane.cost >= leafCost && n < 16) || badRefines >= 3) return makeLeaf(index, prims, area);

    const int a = plane.axis;
    Bounds3 cellBelow = cell, cellAbove = cell;
    cellBelow.max[a] = plane.position;
    cellAbove.min[a] = plane.position;
    auto& children = scratch_[static_cast<size_t>(depth + 1)];
    self.split(in, plane, cellBelow, cellAbove, children[0], children[1]);
    if (n >= kParallelPrimitives) in = Input{};  // a big node's buffers are not worth keeping for reuse
    out_->sah += static_cast<double>(s_.traversalCost) * area;
    const bool belowEmpty = Derived::prims(children[0]).empty(), aboveEmpty = Derived::prims(children[1]).empty();
    const int nextSplits = splits + (belowEmpty || aboveEmpty ? 0 : 1);

    if (n >= kParallelPrimitives && !belowEmpty && !aboveEmpty) {
      auto below = std::make_unique<Derived>(sh_), above = std::make_unique<Derived>(sh_);
      std::swap(below->input(depth + 1), children[0]);
      std::swap(above->input(depth + 1), children[1]);
      tbb::parallel_invoke(
          [&] { below->build(below->input(depth + 1), cellBelow, depth + 1, nextSplits, badRefines); },
          [&] { above->build(above->input(depth + 1), cellAbove, depth + 1, nextSplits, badRefines); });
      // The subtrees live on until the tree is written; their builders' scratch goes now.
      out_->setInteriorOfSubtrees(index, a, plane.position, below->takeTree(), above->takeTree());
      return;
    }
    build(children[0], cellBelow, depth + 1, nextSplits, badRefines);
    out_->setInterior(index, a, plane.position, belowEmpty, aboveEmpty);
    build(children[1], cellAbove, depth + 1, nextSplits, badRefines);
  }

  std::unique_ptr<Subtree> takeTree() { return std::move(out_); }

 protected:
  BuildShared& sh_;
  const KdSettings& s_;

 private:
  void makeLeaf(uint32_t index, const std::vector<KdPrim>& prims, double area) {
    out_->setLeaf(index, prims);
    out_->sah += static_cast<double>(s_.intersectionCost) * static_cast<double>(prims.size()) * area;
  }

  std::vector<std::array<Input, 2>> scratch_;  // by depth: the two children made there (reused)
  size_t unreported_ = 0;                      // nodes made since the last report
  std::unique_ptr<Subtree> out_ = std::make_unique<Subtree>();
};

}  // namespace ll::a4::kdbuild
