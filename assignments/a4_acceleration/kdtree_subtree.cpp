// Writing a KD-tree built in parallel pieces (see kdtree_subtree.h).
#include "kdtree_subtree.h"

#include <algorithm>
#include <utility>

#include <tbb/task_group.h>

#include "core/huge_pages.h"

namespace ll::a4::kdbuild {

void Subtree::setInteriorOfSubtrees(uint32_t index, int axis, float split, std::unique_ptr<Subtree> below,
                                    std::unique_ptr<Subtree> above) {
  nodes_[index] = KdNode::interior(axis, split, index + 2, false, false);
  for (auto* sub : {&below, &above}) {
    nodes_.push_back(KdNode::leafNode(static_cast<uint32_t>(subs_.size()), kLink));
    subs_.push_back(std::move(*sub));
  }
}

void Subtree::countTotals() {
  totalNodes_ = nodes_.size() - subs_.size();
  totalSlots_ = slots_.size();
  for (auto& sub : subs_) {
    sub->countTotals();
    totalNodes_ += sub->totalNodes_;
    totalSlots_ += sub->totalSlots_;
    depth = std::max(depth, sub->depth);
    sah += sub->sah;
  }
}

// Writes this subtree at nodes[nodeBase...] and slots[slotBase...]; its links in parallel.
void Subtree::emit(KdNode* nodes, uint32_t nodeBase, uint32_t* slots, uint32_t slotBase) {
  // Where each local node lands: a link stands for its subtree's nodes.
  std::vector<uint32_t> at(nodes_.size());
  std::vector<std::pair<uint32_t, uint32_t>> subBase(subs_.size());  // a link's node and slot base
  uint32_t node = nodeBase, slot = slotBase;
  for (size_t i = 0; i < nodes_.size(); ++i) {
    at[i] = node;
    const KdNode& nd = nodes_[i];
    if (nd.isLeaf() && nd.count() == kLink) {
      const Subtree& sub = *subs_[nd.first()];
      subBase[nd.first()] = {node, slot};
      node += static_cast<uint32_t>(sub.totalNodes_);
      slot += static_cast<uint32_t>(sub.totalSlots_);
    } else {
      ++node;
      if (nd.isLeaf()) slot += nd.count();
    }
  }
  tbb::task_group subtrees;
  for (size_t k = 0; k < subs_.size(); ++k)
    subtrees.run([&, k] { subs_[k]->emit(nodes, subBase[k].first, slots, subBase[k].second); });
  slot = slotBase;
  for (size_t i = 0; i < nodes_.size(); ++i) {
    const KdNode& nd = nodes_[i];
    if (!nd.isLeaf()) {
      nodes[at[i]] = KdNode::interior(nd.axis(), nd.split(), at[nd.aboveChild()], nd.belowEmpty(), nd.aboveEmpty());
    } else if (nd.count() == kLink) {
      slot += static_cast<uint32_t>(subs_[nd.first()]->totalSlots_);
    } else {
      nodes[at[i]] = KdNode::leafNode(slot, nd.count());
      std::copy_n(slots_.begin() + nd.first(), nd.count(), slots + slot);
      slot += nd.count();
    }
  }
  nodes_ = {};
  slots_ = {};
  subtrees.wait();
  subs_.clear();
}

BuildTotals Subtree::writeTree(KdTree& tree) {
  countTotals();
  tree.nodes.clear();  // exact sizes: no copy to shrink them after
  tree.primIds.clear();
  resizeOnHugePages(tree.nodes, totalNodes_);
  resizeOnHugePages(tree.primIds, totalSlots_);
  emit(tree.nodes.data(), 0, tree.primIds.data(), 0);
  return {depth, sah};
}

}  // namespace ll::a4::kdbuild
