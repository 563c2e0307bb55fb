// Building the BVH (framework code): a pointer tree made with the student's
// splitPrimitives() (A4.1), big subtrees in parallel, then flattened
// depth-first into 32-byte nodes; node spheres for the sphere volume; the
// SAH cost and the memory figures for the statistics.
#include "bvh.h"

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <new>
#include <memory>
#include <span>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include "a4_tasks.h"
#include "core/huge_pages.h"
#include "render/student_task.h"

namespace ll::a4 {

namespace {

struct BuildNode {
  Bounds3 bounds;
  BuildNode* left = nullptr;  // both null for a leaf; nodes live in a NodePool
  BuildNode* right = nullptr;
  size_t first = 0, count = 0;             // the node's primitives: buildPrims[first, first + count)
  size_t subtreeNodes = 1;                 // nodes in this subtree, itself included
};

constexpr size_t kParallelSubtree = 4096;  // primitives; smaller subtrees are built serially
// Below this depth every split halves the primitives, so no tree gets deeper
// than kForcedHalvingDepth + 32 <= kBvhMaxDepth (2^32 primitives at most).
constexpr int kForcedHalvingDepth = kBvhMaxDepth - 40;

// Storage for the build tree: one allocation for the at most 2n - 1 nodes of
// a binary tree over n primitives with no empty leaf. The subtree over
// primitives [f, f + c) owns slots [2f, 2f + 2c - 1): its left subtree (k
// primitives) the first 2k - 1, itself the next, its right subtree the rest
// (in-order). So parallel builders never share a counter -- an atomic one
// cost a seventh of the build on two threads, a malloc per node a fifth.
// BuildNode is trivially destructible: nothing to free.
class NodePool {
 public:
  explicit NodePool(size_t primitives)
      : capacity_(2 * primitives), bytes_(std::make_unique_for_overwrite<std::byte[]>(capacity_ * sizeof(BuildNode))) {
    adviseHugePages(bytes_.get(), capacity_ * sizeof(BuildNode));
  }
  // A node over primitives [first, first + count) with box `bounds`, no children yet.
  // Precondition: slot < 2n - 1, and each slot is made once.
  BuildNode* make(size_t slot, const Bounds3& bounds, size_t first, size_t count) {
    assert(slot < capacity_);
    return new (bytes_.get() + slot * sizeof(BuildNode)) BuildNode{bounds, nullptr, nullptr, first, count};
  }

 private:
  size_t capacity_;
  std::unique_ptr<std::byte[]> bytes_;
};

BuildNode* buildNode(NodePool& pool, std::span<BuildPrim> all, size_t first, size_t count, const SplitSettings& s,
                     int depth) {
  const std::span<BuildPrim> prims = all.subspan(first, count);
  Bounds3 bounds;
  for (const BuildPrim& p : prims) bounds.extend(p.bounds);
  size_t k = 0;  // left child's primitives; 0 or count: a leaf
  if (count >= 2 && depth >= kForcedHalvingDepth) {
    k = count / 2;
    std::nth_element(prims.begin(), prims.begin() + static_cast<std::ptrdiff_t>(k), prims.end(),
                     [](const BuildPrim& a, const BuildPrim& b) { return a.centroid.x < b.centroid.x; });
  } else if (count >= 2) {
    k = splitPrimitives(prims, bounds, s);
  }
  const bool leaf = k == 0 || k >= count;
  BuildNode* node = pool.make(leaf ? 2 * first : 2 * (first + k) - 1, bounds, first, count);
  if (leaf) return node;
  auto buildLeft = [&] { node->left = buildNode(pool, all, first, k, s, depth + 1); };
  auto buildRight = [&] { node->right = buildNode(pool, all, first + k, count - k, s, depth + 1); };
  if (count >= kParallelSubtree)
    tbb::parallel_invoke(buildLeft, buildRight);
  else {
    buildLeft();
    buildRight();
  }
  node->subtreeNodes = 1 + node->left->subtreeNodes + node->right->subtreeNodes;
  return node;
}

// Appends `node`'s subtree in depth-first order; returns the node's index.
uint32_t flatten(const BuildNode& node, std::vector<BvhNode>& out, int depth, int& maxDepth) {
  const auto index = static_cast<uint32_t>(out.size());
  out.emplace_back();
  out[index].lo = node.bounds.min;
  out[index].hi = node.bounds.max;
  maxDepth = std::max(maxDepth, depth);
  if (!node.left) {
    out[index].offset = static_cast<uint32_t>(node.first);
    out[index].count = static_cast<uint32_t>(node.count);
    return index;
  }
  flatten(*node.left, out, depth + 1, maxDepth);
  const uint32_t second = flatten(*node.right, out, depth + 1, maxDepth);
  out[index].offset = second;
  return index;
}

// The first primitive slot and slot count under flat node i.
void subtreeSlots(const std::vector<BvhNode>& nodes, uint32_t i, uint32_t& first, uint32_t& count) {
  uint32_t lo = i, hi = i;
  while (!nodes[lo].isLeaf()) lo = lo + 1;
  while (!nodes[hi].isLeaf()) hi = nodes[hi].offset;
  first = nodes[lo].offset;
  count = nodes[hi].offset + nodes[hi].count - first;
}

// Replaces every node's box by a sphere around the box centre that holds all
// the node's triangle vertices and spheres, padded for rounding.
void makeSpheres(FlatBvh& bvh) {
  const Geometry& g = *bvh.geometry;
  tbb::parallel_for(size_t{0}, bvh.nodes.size(), [&](size_t i) {
    BvhNode& node = bvh.nodes[i];
    const Vec3 centre = 0.5f * (node.lo + node.hi);
    uint32_t first, count;
    subtreeSlots(bvh.nodes, static_cast<uint32_t>(i), first, count);
    float r2 = 0.0f, rSphere = 0.0f;
    for (uint32_t s = first; s < first + count; ++s) {
      const uint32_t prim = bvh.primIds[s];
      if (prim < bvh.triangleCount) {
        const LeafTriangle& t = bvh.triangles[s];
        for (const Vec3& p : {t.p0, t.p1, t.p2}) r2 = std::max(r2, glm::dot(p - centre, p - centre));
      } else {
        const Sphere& sp = g.spheres[prim - bvh.triangleCount];
        rSphere = std::max(rSphere, glm::length(sp.center - centre) + sp.radius);
      }
    }
    const float radius = std::max(std::sqrt(r2), rSphere);
    node.lo = centre;
    node.hi = Vec3(radius * (1.0f + 1e-5f) + 1e-30f, 0.0f, 0.0f);
  });
}

float volumeArea(const BvhNode& n, BoundingVolume v) {
  if (v == BoundingVolume::Sphere) return 4.0f * kPi * n.hi.x * n.hi.x;
  const Vec3 e = glm::max(n.hi - n.lo, Vec3(0.0f));
  return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
}

}  // namespace

double sahCost(const FlatBvh& bvh, const SplitSettings& settings) {
  if (bvh.nodes.empty()) return 0.0;
  const double ct = settings.traversalCost, ci = settings.intersectionCost;
  const double rootArea = volumeArea(bvh.nodes[0], bvh.volume);
  if (!(rootArea > 0.0)) return ci * static_cast<double>(bvh.primIds.size());
  double cost = 0.0;
  for (const BvhNode& n : bvh.nodes) {
    const double p = static_cast<double>(volumeArea(n, bvh.volume)) / rootArea;  // P(a ray through the root enters n)
    cost += p * (n.isLeaf() ? ci * n.count : ct);
  }
  return cost;
}

FlatBvh buildBvh(const Geometry& geometry, const SplitSettings& settings, BoundingVolume volume, BvhBuildInfo* info) {
  FlatBvh bvh;
  bvh.geometry = &geometry;
  bvh.volume = volume;
  bvh.triangleCount = geometry.triangleCount();
  const uint32_t n = geometry.primitiveCount();
  int depth = 0;
  TaskLog buildLog;  // catches the A4.1 stub during the build
  if (n > 0) {
    std::vector<BuildPrim> prims;
    resizeOnHugePages(prims, n);
    tbb::parallel_for(uint32_t{0}, n, [&](uint32_t p) {
      prims[p].bounds = geometry.bounds(p);
      prims[p].centroid = prims[p].bounds.center();
      prims[p].prim = p;
    });
    NodePool pool(n);
    BuildNode* root = nullptr;
    {
      const ScopedTaskLog scope(&buildLog);
      root = buildNode(pool, prims, 0, n, settings, 0);
    }
    reserveOnHugePages(bvh.nodes, root->subtreeNodes);  // exactly: no regrowth, no shrinking copy
    flatten(*root, bvh.nodes, 0, depth);
    bvh.sceneCentre = root->bounds.center();
    bvh.sceneRadius = 0.5f * root->bounds.diagonal();
    resizeOnHugePages(bvh.primIds, n);
    resizeOnHugePages(bvh.triangles, n);
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, n, 4096), [&](const tbb::blocked_range<uint32_t>& range) {
      for (uint32_t s = range.begin(); s < range.end(); ++s) {
        const uint32_t prim = prims[s].prim;
        bvh.primIds[s] = prim;
        if (prim < bvh.triangleCount) {
          const glm::uvec3& tri = geometry.triangles[prim];
          bvh.triangles[s] = {geometry.positions[tri.x], geometry.positions[tri.y], geometry.positions[tri.z]};
        }
      }
    });
    if (volume == BoundingVolume::Sphere) makeSpheres(bvh);
  }
  if (info) {
    info->nodeCount = bvh.nodes.size();
    info->depth = depth;
    info->memoryBytes = bvh.nodes.capacity() * sizeof(BvhNode) + bvh.primIds.capacity() * sizeof(uint32_t) +
                        bvh.triangles.capacity() * sizeof(LeafTriangle);
    info->sahCost = sahCost(bvh, settings);
    info->missingTasks = buildLog.missing();
  }
  for (const auto& [id, what] : buildLog.missing()) reportMissingTask(id.c_str(), what.c_str(), false);  // exact fallback: not striped
  return bvh;
}

}  // namespace ll::a4
