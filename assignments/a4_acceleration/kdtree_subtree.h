// A KD subtree as one build thread makes it (framework code, shared by both
// KD-tree builds): nodes in depth-first order, its leaf slots, and links to
// the subtrees other threads built in parallel. The finished tree is written
// once, straight into its final arrays, with every link replaced by its
// subtree (the order a serial build makes): no node is copied per level.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "kdtree.h"
#include "kdtree_build_support.h"

namespace ll::a4::kdbuild {

class Subtree {
 public:
  // Appends an unset node and returns its index; set it before writeTree().
  uint32_t addNode() {
    nodes_.emplace_back();
    return static_cast<uint32_t>(nodes_.size() - 1);
  }
  size_t nodeCount() const { return nodes_.size(); }

  // Node `index` is a leaf holding `prims`.
  void setLeaf(uint32_t index, const std::vector<KdPrim>& prims) {
    nodes_[index] = KdNode::leafNode(static_cast<uint32_t>(slots_.size()), static_cast<uint32_t>(prims.size()));
    for (const KdPrim& p : prims) slots_.push_back(p.prim);
  }
  // Node `index` splits at (axis, split); its below child is node index + 1 and its above child the next
  // node appended from now on. Call between building the two children.
  void setInterior(uint32_t index, int axis, float split, bool belowEmpty, bool aboveEmpty) {
    nodes_[index] = KdNode::interior(axis, split, static_cast<uint32_t>(nodes_.size()), belowEmpty, aboveEmpty);
  }
  // Node `index` splits at (axis, split), and its children are subtrees built apart (neither empty).
  void setInteriorOfSubtrees(uint32_t index, int axis, float split, std::unique_ptr<Subtree> below,
                             std::unique_ptr<Subtree> above);

  // Writes the tree into tree.nodes and tree.primIds (exact sizes), freeing this subtree and its links
  // as it goes. Returns the depth and SAH sum over all of them.
  BuildTotals writeTree(KdTree& tree);

  int depth = 0;      // edges on the longest root-to-leaf path seen by this builder
  double sah = 0.0;   // this builder's nodes' cost * half area (links excluded)

 private:
  void countTotals();
  void emit(KdNode* nodes, uint32_t nodeBase, uint32_t* slots, uint32_t slotBase);

  std::vector<KdNode> nodes_;    // aboveChild indices within nodes_; a link's first() indexes subs_
  std::vector<uint32_t> slots_;  // leaf slots; leaves' first() within slots_
  std::vector<std::unique_ptr<Subtree>> subs_;
  size_t totalNodes_ = 0, totalSlots_ = 0;  // countTotals(): the whole subtree's, links resolved
  // A leaf count no leaf has (most primitives < 2^30): marks a link node.
  static constexpr uint32_t kLink = (1u << 30) - 1u;
};

}  // namespace ll::a4::kdbuild
