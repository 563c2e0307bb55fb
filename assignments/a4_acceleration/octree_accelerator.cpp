// Accelerator `octree`: the octree of assignment 4, built by buildOctree()
// and queried with the student's traversal (A4.4). Framework code:
// registration, parameters, statistics, the cells for the overlay.
#include <memory>
#include <vector>

#include "a4_tasks.h"
#include "core/timer.h"

namespace ll {

namespace {

class OctreeAccelerator final : public Accelerator {
 public:
  explicit OctreeAccelerator(a4::OctreeSettings settings) : settings_(settings) {}

  void build(const Geometry& geometry) override {
    const Timer timer;
    tree_ = a4::buildOctree(geometry, settings_, &info_);
    buildSeconds_ = timer.seconds();
  }

  bool intersect(const Ray& ray, Hit& hit, QueryCounters& counters) const override {
    return a4::intersectOctree(tree_, ray, hit, counters);
  }

  bool occluded(const Ray& ray, QueryCounters& counters) const override {
    return a4::occludedOctree(tree_, ray, counters);
  }

  // The cells at `depth`, and the leaves above it, except empty leaves (world space).
  std::vector<NodeShape> nodesAtDepth(int depth) const override {
    std::vector<NodeShape> shapes;
    if (tree_.nodes.empty()) return shapes;
    struct Item {
      uint32_t node;
      int depth;
      Vec3 lo, hi;
    };
    std::vector<Item> stack{{0u, 0, tree_.bounds.min, tree_.bounds.max}};
    while (!stack.empty()) {
      const Item item = stack.back();
      stack.pop_back();
      const a4::OctreeNode& n = tree_.nodes[item.node];
      if (item.depth == depth || n.isLeaf()) {
        if (n.isLeaf() && n.count == 0) continue;
        NodeShape shape;
        shape.box.min = item.lo;
        shape.box.max = item.hi;
        shape.leaf = n.isLeaf();
        shapes.push_back(shape);
        continue;
      }
      for (int i = 7; i >= 0; --i) {
        Item child{n.offset + static_cast<uint32_t>(i), item.depth + 1, {}, {}};
        a4::octreeChildCell(item.lo, item.hi, i, child.lo, child.hi);
        stack.push_back(child);
      }
    }
    return shapes;
  }

  AcceleratorStats stats() const override { return treeStats(buildSeconds_, info_); }

 private:
  a4::OctreeSettings settings_;
  a4::Octree tree_;
  a4::OctreeBuildInfo info_;
  double buildSeconds_ = 0.0;
};

}  // namespace

AcceleratorInfo octreeAccelerator() {
  return {"octree",
          "octree (assignment 4): cells cut at their centre into eight, primitives in every cell they touch, "
          "children visited in the order the ray enters them",
          {ParamDecl::integer("max_depth", 14, 0, a4::kOctreeMaxDepth, "deepest leaf (the root is depth 0)"),
           ParamDecl::integer("max_leaf", 8, 1, 64, "cells with at most this many primitives are not subdivided")},
          [](const ParamSet& p) -> std::unique_ptr<Accelerator> {
            a4::OctreeSettings s;
            s.maxDepth = p.getInt("max_depth");
            s.maxLeaf = p.getInt("max_leaf");
            return std::make_unique<OctreeAccelerator>(s);
          }};
}

}  // namespace ll
