// Building the KD-tree (framework code): the primitives' boxes, the depth
// limit and the rounding pad, then one of two top-down SAH builds
// (kdtree_sweep_build.cpp, the default, or kdtree_binned_build.cpp), then the
// statistics. Both choose one axis-aligned plane per node by the surface area
// heuristic; primitives whose box reaches across the plane go to both
// children, where a triangle's box shrinks to the box of the part of the
// triangle inside the child's cell ("perfect splits", Havran 2000; padded for
// rounding). Nodes with at most maxLeaf primitives still take a plane that
// cuts off empty space when that lowers the true SAH cost.
#include "kdtree.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "core/huge_pages.h"
#include "kdtree_build_support.h"

namespace ll::a4 {

KdTree buildKdTree(const Geometry& geometry, const KdSettings& settings, KdBuildInfo* info) {
  KdTree tree;
  tree.geometry = &geometry;
  tree.triangleCount = geometry.triangleCount();
  const uint32_t n = geometry.primitiveCount();
  int depth = 0;
  double sah = 0.0;
  if (n > 0) {
    // The boxes and the scene's box: in parallel, as the build.
    std::vector<kdbuild::KdPrim> prims;
    resizeOnHugePages(prims, n);
    tree.bounds = tbb::parallel_reduce(
        tbb::blocked_range<uint32_t>(0, n, 16384), Bounds3{},
        [&](const tbb::blocked_range<uint32_t>& r, Bounds3 box) {
          for (uint32_t p = r.begin(); p < r.end(); ++p) {
            prims[p] = {geometry.bounds(p), p};
            box.extend(prims[p].box);
          }
          return box;
        },
        [](Bounds3 x, const Bounds3& y) {
          x.extend(y);
          return x;
        });
    tree.sceneCentre = tree.bounds.center();
    tree.sceneRadius = 0.5f * tree.bounds.diagonal();
    const int maxDepth = kdbuild::maxSplits(settings.maxDepth, n, kKdMaxDepth);
    tree.storeTrianglesByPrimitive();
    const float pad = kdbuild::roundingPad(tree.bounds);
    const kdbuild::BuildTotals totals =
        settings.build == KdBuild::Sweep ? kdbuild::buildSweep(tree, std::move(prims), settings, maxDepth, pad)
                                         : kdbuild::buildBinned(tree, std::move(prims), settings, maxDepth, pad);
    depth = totals.depth;
    const double rootArea = kdbuild::halfArea(tree.bounds);
    sah = rootArea > 0.0 ? totals.sahSum / rootArea : static_cast<double>(settings.intersectionCost) * n;
    tree.nodes.shrink_to_fit();
    tree.primIds.shrink_to_fit();
    tree.triangles.shrink_to_fit();
  }
  if (info) {
    info->nodeCount = tree.nodes.size();
    info->leafSlots = tree.primIds.size();
    info->depth = depth;
    info->memoryBytes = tree.nodes.capacity() * sizeof(KdNode) + tree.memoryBytes();
    info->sahCost = sah;
  }
  return tree;
}

}  // namespace ll::a4
