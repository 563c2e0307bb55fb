// Accelerator `kdtree`: the SAH KD-tree of assignment 4, built by
// buildKdTree() and queried with the student's traversal (A4.3). Framework
// code: registration, parameters, statistics, the cells for the overlay.
#include <memory>
#include <utility>
#include <vector>

#include "a4_tasks.h"
#include "core/timer.h"

namespace ll {

namespace {

class KdTreeAccelerator final : public Accelerator {
 public:
  explicit KdTreeAccelerator(a4::KdSettings settings) : settings_(settings) {}

  void build(const Geometry& geometry) override {
    const Timer timer;
    tree_ = a4::buildKdTree(geometry, settings_, &info_);
    buildSeconds_ = timer.seconds();
  }

  bool intersect(const Ray& ray, Hit& hit, QueryCounters& counters) const override {
    return a4::intersectKdTree(tree_, ray, hit, counters);
  }

  bool occluded(const Ray& ray, QueryCounters& counters) const override {
    return a4::occludedKdTree(tree_, ray, counters);
  }

  // The cells at `depth`, and the leaves above it (world space).
  std::vector<NodeShape> nodesAtDepth(int depth) const override {
    std::vector<NodeShape> shapes;
    if (tree_.nodes.empty()) return shapes;
    struct Item {
      uint32_t node;
      int depth;
      Bounds3 cell;
    };
    std::vector<Item> stack{{0u, 0, tree_.bounds}};
    while (!stack.empty()) {
      const Item item = stack.back();
      stack.pop_back();
      const a4::KdNode& n = tree_.nodes[item.node];
      if (item.depth == depth || n.isLeaf()) {
        NodeShape shape;
        shape.box = item.cell;
        shape.leaf = n.isLeaf();
        shapes.push_back(shape);
        continue;
      }
      Bounds3 below = item.cell, above = item.cell;
      below.max[n.axis()] = n.split();
      above.min[n.axis()] = n.split();
      stack.push_back({n.aboveChild(), item.depth + 1, above});
      stack.push_back({item.node + 1, item.depth + 1, below});
    }
    return shapes;
  }

  AcceleratorStats stats() const override { return treeStats(buildSeconds_, info_); }

 private:
  a4::KdSettings settings_;
  a4::KdTree tree_;
  a4::KdBuildInfo info_;
  double buildSeconds_ = 0.0;
};

}  // namespace

AcceleratorInfo kdtreeAccelerator() {
  return {"kdtree",
          "KD-tree (assignment 4): space cut by SAH planes, primitives across a plane on both sides, front-to-back "
          "traversal",
          {ParamDecl::integer("max_depth", 0, 0, a4::kKdMaxDepth, "deepest leaf; 0 = 8 + 1.3 log2(primitives)"),
           ParamDecl::integer("max_leaf", 2, 1, 64,
                              "nodes with at most this many primitives become leaves, unless an "
                              "empty-space cut is cheaper"),
           ParamDecl::real("traversal_cost", 1.0, 0.01, 100.0, "SAH: cost of one traversal step"),
           ParamDecl::real("intersection_cost", 1.5, 0.01, 100.0, "SAH: cost of one primitive test"),
           ParamDecl::real("empty_bonus", 0.5, 0.0, 1.0,
                           "SAH: a split with an empty side costs (1 - empty_bonus) as much"),
           ParamDecl::choice("build", "sweep", {"sweep", "binned"},
                             "how each plane is found: sweep = every face of every box, swept in sorted order "
                             "(Wald and Havran 2006); binned = bin boundaries and the primitives' box faces: about "
                             "twice as fast to build, trees ~3 % costlier by the SAH"),
           ParamDecl::integer("bins", 32, 2, 64,
                              "bins per axis: the binned build's bins - 1 evenly spaced candidate planes, which "
                              "the sweep also offers between faces")},
          [](const ParamSet& p) -> std::unique_ptr<Accelerator> {
            a4::KdSettings s;
            s.maxDepth = p.getInt("max_depth");
            s.maxLeaf = p.getInt("max_leaf");
            s.traversalCost = static_cast<float>(p.getFloat("traversal_cost"));
            s.intersectionCost = static_cast<float>(p.getFloat("intersection_cost"));
            s.emptyBonus = static_cast<float>(p.getFloat("empty_bonus"));
            s.build = p.getChoice("build") == "binned" ? a4::KdBuild::Binned : a4::KdBuild::Sweep;
            s.bins = p.getInt("bins");
            return std::make_unique<KdTreeAccelerator>(s);
          }};
}

}  // namespace ll
