// Accelerator `bvh`: the bounding volume hierarchy of assignment 4, built by
// buildBvh() with the student's split (A4.1) and queried with the student's
// traversal (A4.2). Framework code: registration, parameters, statistics.
#include <memory>
#include <utility>
#include <vector>

#include "a4_tasks.h"
#include "core/timer.h"
#include "render/student_task.h"

namespace ll {

namespace {

class BvhAccelerator final : public Accelerator {
 public:
  BvhAccelerator(a4::SplitSettings settings, a4::BoundingVolume volume) : settings_(settings), volume_(volume) {}

  void build(const Geometry& geometry) override {
    const Timer timer;
    bvh_ = a4::buildBvh(geometry, settings_, volume_, &info_);
    buildSeconds_ = timer.seconds();
  }

  bool intersect(const Ray& ray, Hit& hit, QueryCounters& counters) const override {
    reportBuildStubs();
    return a4::intersectBvh(bvh_, ray, hit, counters);
  }

  bool occluded(const Ray& ray, QueryCounters& counters) const override {
    reportBuildStubs();
    return a4::occludedBvh(bvh_, ray, counters);
  }

  std::vector<NodeShape> nodesAtDepth(int depth) const override {
    std::vector<NodeShape> shapes;
    if (bvh_.nodes.empty()) return shapes;
    std::vector<std::pair<uint32_t, int>> stack{{0u, 0}};  // (node, its depth)
    while (!stack.empty()) {
      const auto [index, d] = stack.back();
      stack.pop_back();
      const a4::BvhNode& n = bvh_.nodes[index];
      if (d == depth || n.isLeaf()) {
        NodeShape shape;
        shape.leaf = n.isLeaf();
        if (bvh_.volume == a4::BoundingVolume::Sphere) {
          shape.isSphere = true;
          shape.center = n.lo;
          shape.radius = n.hi.x;
          shape.box.extend(n.lo - Vec3(n.hi.x));
          shape.box.extend(n.lo + Vec3(n.hi.x));
        } else {
          shape.box.extend(n.lo);
          shape.box.extend(n.hi);
        }
        shapes.push_back(shape);
        continue;
      }
      stack.emplace_back(n.offset, d + 1);
      stack.emplace_back(index + 1, d + 1);
    }
    return shapes;
  }

  AcceleratorStats stats() const override { return treeStats(buildSeconds_, info_); }

 private:
  // A stub that ran during the build made this tree a brute-force leaf: say
  // so on every query, as the query stubs do.
  void reportBuildStubs() const {
    for (const auto& [id, what] : info_.missingTasks)
      reportMissingTask(id.c_str(), what.c_str(), false);  // exact fallback: not striped
  }

  a4::SplitSettings settings_;
  a4::BoundingVolume volume_;
  a4::FlatBvh bvh_;
  a4::BvhBuildInfo info_;
  double buildSeconds_ = 0.0;
};

a4::SplitMethod splitMethod(const std::string& name) {
  if (name == "median") return a4::SplitMethod::Median;
  if (name == "equal-counts") return a4::SplitMethod::EqualCounts;
  return a4::SplitMethod::Sah;
}

}  // namespace

AcceleratorInfo bvhAccelerator() {
  return {"bvh",
          "bounding volume hierarchy (assignment 4): binary tree, flattened into 32-byte nodes, nearer child first",
          {ParamDecl::choice("split", "sah", {"median", "equal-counts", "sah"},
                             "how a node splits: median = midpoint of the widest centroid axis, equal-counts = half "
                             "the primitives each side, sah = binned surface area heuristic"),
           ParamDecl::integer("max_leaf", 4, 1, 64, "most primitives in one leaf"),
           ParamDecl::integer("bins", 16, 2, 64, "SAH bins per axis"),
           ParamDecl::choice("volume", "box", {"box", "sphere"},
                             "bounding volume of the nodes: axis-aligned boxes, or spheres (looser, more nodes visited)")},
          [](const ParamSet& p) -> std::unique_ptr<Accelerator> {
            a4::SplitSettings s;
            s.method = splitMethod(p.getChoice("split"));
            s.maxLeaf = p.getInt("max_leaf");
            s.bins = p.getInt("bins");
            const auto volume =
                p.getChoice("volume") == "sphere" ? a4::BoundingVolume::Sphere : a4::BoundingVolume::Box;
            return std::make_unique<BvhAccelerator>(s, volume);
          }};
}

}  // namespace ll
