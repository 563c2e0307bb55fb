// Accelerator `bvh4`: a 4-wide bounding volume hierarchy traversed with SSE,
// the framework's fast path ("how production tracers do it"). The binary
// `bvh` stays assignment 4's structure; this one is framework code and never
// runs student code.
//
// Build: binned SAH (Wald, "On fast Construction of SAH-based Bounding Volume
// Hierarchies", 2007) over primitive centroids, big subtrees in parallel
// (oneTBB). The binary SAH tree is collapsed into 4-wide nodes while it is
// built: a node's children start as its whole range, and the child with the
// largest surface area is split again until there are four -- pulling up the
// grandchildren of the binary tree greedily by area, as in Wald, Benthin and
// Boulos, "Getting Rid of Packets", RT 2008 (Embree's builder) and Dammertz,
// Hanika and Keller, "Shallow Bounding Volume Hierarchies for Fast SIMD Ray
// Tracing of Incoherent Rays", EGSR 2008.
//
// Query: the four child boxes of a node are tested at once (SSE, x86-64's
// baseline: no AVX needed), the children hit are visited nearest first, and
// leaves test four triangles at once with the very arithmetic of the
// framework's watertight triangle test (Woop et al. 2013), and the lanes it
// cannot rule out -- hits, edge cases, spheres -- with that test and the
// sphere test themselves, so hits are bit-identical to brute force (`none`):
// the same t and, on equal t, the same (smallest) primitive id.
#pragma once

#include <cstdint>
#include <vector>

#include "accel/accelerator.h"
#include "accel/ray_triangle.h"
#include "core/math.h"
#include "scene/geometry.h"

namespace ll {

// One node: the boxes of up to four children as structure-of-arrays rows
// (box[side][axis][child], side 0 = min corner, 1 = max corner; world space),
// so one SSE instruction handles one plane of all four boxes. 128 bytes, two
// cache lines, aligned to 128 so they are the pair the L2's adjacent-line
// prefetcher fetches together. An unused child slot has an empty box (min +inf, max -inf),
// which no ray enters, and child == kEmpty.
struct alignas(128) WideBvhNode {
  static constexpr uint32_t kEmpty = 0xffffffffu;
  float box[2][3][4];
  uint32_t child[4];  // count == 0: index of an interior node; count > 0: its first packet
  uint32_t count[4];  // primitives of a leaf child, in packets [child, child + ceil(count / 4)); 0 = not a leaf
  bool used(int i) const { return child[i] != kEmpty; }
  bool isLeaf(int i) const { return count[i] > 0; }
  Bounds3 childBounds(int i) const {
    Bounds3 b;
    b.min = Vec3(box[0][0][i], box[0][1][i], box[0][2][i]);
    b.max = Vec3(box[1][0][i], box[1][1][i], box[1][2][i]);
    return b;
  }
};
static_assert(sizeof(WideBvhNode) == 128, "a 4-wide node fills two cache lines");

// Up to four primitives of one leaf, structure-of-arrays like the nodes, so
// one SSE instruction handles one coordinate of four triangles: the lanes'
// ids and, for a triangle, its vertices (world space: the very floats of the
// Geometry, so the triangle test gives the same t as brute force). A lane
// holding another primitive than a triangle, or a triangle with collinear
// vertices (never hit), has all vertices 0; an unused lane
// has id kEmpty. 160 bytes; a leaf of n primitives is ceil(n / 4) packets side
// by side, its first n lanes in order.
struct alignas(32) WideBvhPacket {
  static constexpr uint32_t kEmpty = 0xffffffffu;
  Triangles4 triangles;  // v[vertex][axis][lane]
  uint32_t prim[4];      // id in the Geometry, per lane
  Vec3 vertex(int k, int lane) const {
    return Vec3(triangles.v[k][0][lane], triangles.v[k][1][lane], triangles.v[k][2][lane]);
  }
};
static_assert(sizeof(WideBvhPacket) == 160, "four triangles and their ids");

struct WideBvhSettings {
  int maxLeaf = 4;  // most primitives in one leaf (1..16); smaller leaves are made when the SAH says so
  int bins = 16;    // SAH bins per axis (2..64)
};

// Deepest path of binary splits the build makes (forced halving beyond
// kWideBvhMaxDepth - 32 splits): a 4-wide tree is never deeper.
constexpr int kWideBvhMaxDepth = 96;

// The built structure. Every primitive sits in exactly one packet lane; a
// leaf's packets are contiguous, and packets follow the tree's depth-first order.
struct WideBvh {
  const Geometry* geometry = nullptr;
  std::vector<WideBvhNode> nodes;          // nodes[0] is the root (depth-first order); empty: no primitives
  std::vector<WideBvhPacket> packets;      // the leaves' primitives (ids, and vertices of triangles)
  uint32_t triangleCount = 0;              // primitive ids below this are triangles
  Vec3 sceneCentre{0.0f};                  // a sphere around every primitive (world space), for rounding bounds
  float sceneRadius = 0.0f;
  int depth = 0;         // edges on the longest root-to-leaf path (a leaf child of the root: 1)
  double sahCost = 0.0;  // expected cost per ray: one unit per 4-wide node visited and per packet tested
  size_t memoryBytes() const {
    return nodes.capacity() * sizeof(WideBvhNode) + packets.capacity() * sizeof(WideBvhPacket);
  }
};

// Builds over `geometry`, which must outlive the result.
WideBvh buildWideBvh(const Geometry& geometry, const WideBvhSettings& settings);

// Closest hit with ray.tmin < t < ray.tmax, exactly as brute force finds it.
// Counters: one node per 4-wide node visited, one per primitive tested.
bool intersectWideBvh(const WideBvh& bvh, const Ray& ray, Hit& hit, QueryCounters& counters);
// Whether anything is hit with ray.tmin < t < ray.tmax; stops at the first hit.
bool occludedWideBvh(const WideBvh& bvh, const Ray& ray, QueryCounters& counters);

// The registration (framework/modules/module_list.h).
AcceleratorInfo wideBvhAccelerator();

}  // namespace ll
