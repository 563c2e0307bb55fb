// Assignment 4 -- Acceleration structures: a bounding volume hierarchy, a
// KD-tree, an octree and a BSP tree. The functions you write. Each lives in its own .cpp file between the
// markers of its task ID; the accelerators `bvh`, `kdtree`, `octree` and `bsp`
// (*_accelerator.cpp) call them. Until you write one, its stub reports the
// task as missing and the task's reference (the course's solution, object
// code) answers in its place: the same picture. See README.md for the handout
// and the --reference switches.
#pragma once

#include <cstddef>
#include <span>

#include "accel/accelerator.h"
#include "bsp.h"
#include "bvh.h"
#include "kdtree.h"
#include "octree.h"

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

// A4.3 KD-tree traversal. The closest hit of `ray` (ray.tmin < t < ray.tmax)
// among the primitives in `tree`, exactly as brute force finds it
// (closerPrimitiveHit() in leaves; a primitive may sit in several leaves).
// Clip the ray to tree.bounds, then walk front to back: at an interior node
// the cell's interval [tNear, tFar] is cut where the ray crosses the split
// plane; visit the child on the origin's side first and keep the other one
// with its interval on a stack of kKdStackSize entries. Axis-parallel rays
// never cross (tSplit = +-infinity), or lie in the plane (NaN: both
// children, the whole interval). Stop once the closest hit lies inside the
// current cell (allow r.tSlack for rounding); a hit beyond the cell's end
// may still lose to the next cell. Count nodes and primitives as in A4.2.
// Optional, for speed: skip children flagged empty (KdNode::belowEmpty(),
// aboveEmpty()), and test each primitive once per ray (Mailbox, mailbox.h).
bool intersectKdTree(const KdTree& tree, const Ray& ray, Hit& hit, QueryCounters& counters);

// A4.3 (any hit): whether anything is hit with ray.tmin < t < ray.tmax.
bool occludedKdTree(const KdTree& tree, const Ray& ray, QueryCounters& counters);

// A4.4 Octree traversal. The closest hit as in A4.3. At an interior node
// find which of the eight children (octreeChildCell()) the ray enters and
// where, visit them nearest first (the others on a stack of
// kOctreeStackSize entries, with their cells), and stop once the closest hit
// lies inside the current cell. Optional: a Mailbox, as in A4.3.
bool intersectOctree(const Octree& tree, const Ray& ray, Hit& hit, QueryCounters& counters);

// A4.4 (any hit): whether anything is hit with ray.tmin < t < ray.tmax.
bool occludedOctree(const Octree& tree, const Ray& ray, QueryCounters& counters);

// A4.5 BSP tree traversal (optional). The closest hit as in A4.3, across
// planes of any orientation: at an interior node the origin's signed
// distance to the plane, dot(normal, origin) - offset, says which child it
// starts in (below when negative), and the ray crosses the plane at tSplit =
// -distance / dot(normal, dir) -- +-infinity for a ray parallel to it, NaN
// for a ray lying in it (both children, the whole interval); where
// node.axis() names an axis the plane is x[axis] = offset (optional fast
// path). Otherwise the walk is A4.3's: front to back, a stack of
// kBspStackSize entries, stop once the closest hit lies inside the current
// cell (allow r.tSlack).
bool intersectBsp(const BspTree& tree, const Ray& ray, Hit& hit, QueryCounters& counters);

// A4.5 (any hit): whether anything is hit with ray.tmin < t < ray.tmax.
bool occludedBsp(const BspTree& tree, const Ray& ray, QueryCounters& counters);

}  // namespace ll::a4
