// Assignment 4 -- Acceleration structures: a bounding volume hierarchy.
// The two functions you write. Each lives in its own .cpp file between the
// markers of its task ID; the accelerator `bvh` (bvh_accelerator.cpp) calls
// them. Until you write one, its stub reports the task as missing and falls
// back to brute force (A4.1: one leaf holding everything; A4.2: test every
// primitive), so renders stay correct -- only slow. See README.md.
#pragma once

#include <cstddef>
#include <span>

#include "accel/accelerator.h"
#include "bvh.h"

namespace ll::a4 {

// A4.1 BVH build: the split. `prims` (n >= 2 of them) are the primitives of
// one node; `bounds` is the union of their boxes (world space). Reorder
// `prims` in place so that the left child gets prims[0, k) and the right
// child prims[k, n), and return k. Returning 0 (or n) makes the node a leaf
// holding all n. The framework calls you recursively on both halves.
//   Median:      split the widest axis of the centroids' box at its midpoint.
//   EqualCounts: the same axis, half of the primitives on each side.
//   Sah:         the surface area heuristic over settings.bins bins on each
//                axis: cost = traversalCost + intersectionCost *
//                (A_left n_left + A_right n_right) / A_node; make a leaf when
//                that is no cheaper than intersectionCost * n and n <= maxLeaf.
// Every method: at most settings.maxLeaf primitives per leaf, whatever the
// input (identical centroids, flat boxes, all primitives on one side).
size_t splitPrimitives(std::span<BuildPrim> prims, const Bounds3& bounds, const SplitSettings& settings);

// A4.2 BVH traversal. The closest hit of `ray` (ray.tmin < t < ray.tmax)
// among the primitives in `bvh`, exactly as brute force finds it: use
// closerPrimitiveHit() in leaves (it breaks ties as brute force does). On a
// miss, hit.prim stays Hit::kNone. Visit the nearer child first, keep the
// farther one on a small fixed-size stack (kBvhStackSize entries), and skip
// whatever starts beyond the closest hit found so far. Count every node you
// enter in counters.nodesVisited and every primitive you test in
// counters.primitivesTested. bvh.volume says which bounding volume the
// nodes hold: rayEntersBox() or rayEntersSphere() (bvh_ray_tests.h).
bool intersectBvh(const FlatBvh& bvh, const Ray& ray, Hit& hit, QueryCounters& counters);

// A4.2 (any hit): whether anything is hit with ray.tmin < t < ray.tmax; stop
// at the first primitive hit (anyPrimitiveHit()).
bool occludedBvh(const FlatBvh& bvh, const Ray& ray, QueryCounters& counters);

}  // namespace ll::a4
