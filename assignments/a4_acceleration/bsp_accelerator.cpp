// Accelerator `bsp`: the BSP tree of assignment 4, built by buildBspTree()
// and queried with the student's traversal (A4.5). Framework code:
// registration, parameters, statistics, the convex cells for the overlay.
#include <memory>
#include <vector>

#include "a4_tasks.h"
#include "bsp_cell.h"
#include "core/timer.h"

namespace ll {

namespace {

class BspAccelerator final : public Accelerator {
 public:
  explicit BspAccelerator(a4::BspSettings settings) : settings_(settings) {}

  void build(const Geometry& geometry) override {
    const Timer timer;
    tree_ = a4::buildBspTree(geometry, settings_, &info_);
    buildSeconds_ = timer.seconds();
  }

  bool intersect(const Ray& ray, Hit& hit, QueryCounters& counters) const override {
    return a4::intersectBsp(tree_, ray, hit, counters);
  }

  bool occluded(const Ray& ray, QueryCounters& counters) const override {
    return a4::occludedBsp(tree_, ray, counters);
  }

  // The cells at `depth`, and the leaves above it, as the edges of their
  // convex polyhedra (the scene's box cut by the planes on the way down; world space).
  std::vector<NodeShape> nodesAtDepth(int depth) const override {
    std::vector<NodeShape> shapes;
    if (tree_.nodes.empty()) return shapes;
    struct Item {
      uint32_t node;
      int depth;
      a4::ConvexCell cell;
    };
    std::vector<Item> stack;
    stack.push_back({0u, 0, a4::ConvexCell::box(tree_.bounds)});
    while (!stack.empty()) {
      Item item = std::move(stack.back());
      stack.pop_back();
      const a4::BspNode& n = tree_.nodes[item.node];
      if (item.depth == depth || n.isLeaf()) {
        NodeShape shape;
        shape.box = item.cell.bounds();
        shape.edges = item.cell.edges();
        shape.leaf = n.isLeaf();
        shapes.push_back(std::move(shape));
        continue;
      }
      a4::ConvexCell below, above;
      item.cell.split(n.normal, n.offset, below, above);
      if (!above.empty()) stack.push_back({n.aboveChild(), item.depth + 1, std::move(above)});
      if (!below.empty()) stack.push_back({item.node + 1, item.depth + 1, std::move(below)});
    }
    return shapes;
  }

  AcceleratorStats stats() const override { return treeStats(buildSeconds_, info_); }

 private:
  a4::BspSettings settings_;
  a4::BspTree tree_;
  a4::BspBuildInfo info_;
  double buildSeconds_ = 0.0;
};

}  // namespace

AcceleratorInfo bspAccelerator() {
  return {"bsp",
          "BSP tree (assignment 4): space cut by planes of any orientation -- the triangles' own planes and axis "
          "planes, chosen by the SAH over convex cells -- front-to-back traversal",
          {ParamDecl::integer("max_depth", 0, 0, a4::kBspMaxDepth, "deepest leaf; 0 = 8 + 1.3 log2(primitives)"),
           ParamDecl::integer("max_leaf", 2, 1, 64, "nodes with at most this many primitives become leaves"),
           ParamDecl::real("traversal_cost", 1.0, 0.01, 100.0, "SAH: cost of one traversal step (a plane test)"),
           ParamDecl::real("intersection_cost", 1.5, 0.01, 100.0, "SAH: cost of one primitive test"),
           ParamDecl::integer("triangle_planes", 2, 0, 256,
                              "candidate planes per node taken from the node's triangles (auto-partition); 0 = "
                              "axis-aligned planes only, a KD-tree"),
           ParamDecl::integer("axis_planes", 32, 1, 64, "candidate axis-aligned planes per axis: this many - 1")},
          [](const ParamSet& p) -> std::unique_ptr<Accelerator> {
            a4::BspSettings s;
            s.maxDepth = p.getInt("max_depth");
            s.maxLeaf = p.getInt("max_leaf");
            s.traversalCost = static_cast<float>(p.getFloat("traversal_cost"));
            s.intersectionCost = static_cast<float>(p.getFloat("intersection_cost"));
            s.triangleCandidates = p.getInt("triangle_planes");
            s.axisCandidates = p.getInt("axis_planes");
            return std::make_unique<BspAccelerator>(s);
          }};
}

}  // namespace ll
