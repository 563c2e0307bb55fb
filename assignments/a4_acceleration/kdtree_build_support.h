// What both KD-tree builds share (framework code): a primitive as one node's
// build sees it, the SAH's half surface area, the box of a triangle clipped
// to a cell ("perfect splits", Havran 2000), and the statistics a build
// gathers while it writes nodes.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/math.h"

namespace ll::a4::kdbuild {

// The most splits above a leaf: `setting` when positive, else PBRT's rule 8 + 1.3 log2(n); at most `cap`.
inline int maxSplits(int setting, uint32_t n, int cap) {
  const int automatic = static_cast<int>(std::lround(8.0 + 1.3 * std::log2(static_cast<double>(n))));
  return std::clamp(setting > 0 ? setting : automatic, 0, cap);
}

// World-space slack for the rounding of clipping and plane distances in a scene with box `scene`: a few
// ulps of its coordinates, padded by far more.
inline float roundingPad(const Bounds3& scene) {
  const Vec3 far = glm::max(glm::abs(scene.min), glm::abs(scene.max));
  return 1e-5f * (std::max({far.x, far.y, far.z}) + scene.diagonal());
}

// A primitive as one node's build sees it: its box clipped to the node's cell (world space).
struct KdPrim {
  Bounds3 box;
  uint32_t prim = 0;
};

// Half the surface area of `b` (0 for an empty box): the SAH's measure of how often a ray crosses b.
inline float halfArea(const Bounds3& b) {
  const Vec3 e = glm::max(b.max - b.min, Vec3(0.0f));
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

// The box of the part of triangle (p0, p1, p2) inside `cell` (Sutherland-
// Hodgman against the six planes), or an empty box if there is none.
inline Bounds3 clippedTriangleBox(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Bounds3& cell) {
  std::array<Vec3, 9> bufferA{p0, p1, p2}, bufferB;  // a triangle cut by six planes has at most 9 corners
  Vec3* poly = bufferA.data();
  Vec3* next = bufferB.data();
  size_t n = 3;
  for (int a = 0; a < 3 && n > 0; ++a)
    for (int side = 0; side < 2 && n > 0; ++side) {
      const float plane = side == 0 ? cell.min[a] : cell.max[a];
      auto inside = [&](const Vec3& v) { return side == 0 ? v[a] >= plane : v[a] <= plane; };
      bool allInside = true;  // the common case deep in a tree: this plane cuts nothing off
      for (size_t i = 0; i < n && allInside; ++i) allInside = inside(poly[i]);
      if (allInside) continue;
      size_t m = 0;
      for (size_t i = 0; i < n; ++i) {
        const Vec3& u = poly[i];
        const Vec3& v = poly[i + 1 == n ? 0 : i + 1];
        const bool uIn = inside(u), vIn = inside(v);
        if (uIn) next[m++] = u;
        if (uIn != vIn) {
          const float s = (plane - u[a]) / (v[a] - u[a]);
          Vec3 x = u + s * (v - u);
          x[a] = plane;
          next[m++] = x;
        }
      }
      std::swap(poly, next);
      n = m;
    }
  Bounds3 b;
  for (size_t i = 0; i < n; ++i) b.extend(poly[i]);
  return b;
}

// The part of triangle p (p.box: its box clipped so far) inside `cell`, padded
// by `pad` (>= the clipping's rounding, world units) and kept within p.box and
// the cell; empty if the triangle stays more than pad away from the cell.
inline Bounds3 clippedBox(const KdPrim& p, const Vec3& p0, const Vec3& p1, const Vec3& p2, const Bounds3& cell,
                          float pad) {
  Bounds3 grown = cell;
  grown.min -= Vec3(pad);
  grown.max += Vec3(pad);
  Bounds3 b = clippedTriangleBox(p0, p1, p2, grown);
  if (b.empty()) return b;
  b.min = glm::max(b.min - Vec3(pad), glm::max(p.box.min, cell.min));
  b.max = glm::min(b.max + Vec3(pad), glm::min(p.box.max, cell.max));
  return b;
}

}  // namespace ll::a4::kdbuild

namespace ll::a4 {
struct KdTree;
struct KdSettings;
}  // namespace ll::a4

namespace ll::a4::kdbuild {

// What a build reports besides the nodes.
struct BuildTotals {
  int depth = 0;        // edges on the longest root-to-leaf path
  double sahSum = 0.0;  // sum over nodes of cost * half area (divide by the root's for the SAH cost)
};

// Each build appends the tree over `prims` (boxes within tree.bounds,
// consumed) to tree.nodes and tree.primIds. maxDepth: most splits that leave
// primitives on both sides; pad: see clippedBox().
BuildTotals buildBinned(KdTree& tree, std::vector<KdPrim> prims, const KdSettings& s, int maxDepth, float pad);
BuildTotals buildSweep(KdTree& tree, std::vector<KdPrim> prims, const KdSettings& s, int maxDepth, float pad);

}  // namespace ll::a4::kdbuild
