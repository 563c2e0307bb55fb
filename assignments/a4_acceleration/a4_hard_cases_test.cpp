// The hard cases of tests/numerics, graded for the traversal each task writes
// (A4.2 the BVH, A4.3 the KD-tree, A4.4 the octree, A4.5 the BSP tree): every ray has an exact
// answer, and each failure says which case broke and why it matters.
#include <gtest/gtest.h>

#include "numerics/accelerator_hard_cases.h"
#include "test_support.h"

namespace ll {
namespace {

using numerics::OnlyAccelerator;

constexpr const char* kSlab =
    "hard case: axis-parallel rays with -0 and +0 direction components through flat boxes. 1/d is -inf or "
    "+inf, and an origin on a box's face gives 0 * inf = NaN in a naive slab test: a traversal that then "
    "drops the box misses whatever is inside it (holes in flat walls, light leaking through floors).";
constexpr const char* kPlane =
    "hard case: rays parallel to a triangle's plane or lying in it. The triangle must be missed and the wall "
    "behind it still found: the nodes of such a ray's cell must not be skipped, nor the search cut short.";
constexpr const char* kFan =
    "hard case: rays exactly through the shared edges and the shared vertex of a fan of triangles. Never a "
    "miss (a crack lets light through a closed mesh) and never a second hit of the neighbour past the sheet: "
    "the traversal must visit every cell that holds the edge.";
constexpr const char* kMesh =
    "hard case: rays through a closed mesh's edges, continued past every hit: exactly two crossings. A "
    "traversal that stops early in a cell that does not hold the hit, or revisits one, breaks glass and shadows.";

void allCases(const char* accelerator) {
  const OnlyAccelerator only(accelerator);
  {
    SCOPED_TRACE(kSlab);
    numerics::axisParallelRaysThroughFlatBoxes();
  }
  {
    SCOPED_TRACE(kPlane);
    numerics::raysParallelToOrInATrianglesPlane();
  }
  {
    SCOPED_TRACE(kFan);
    numerics::fanSharedEdgesAndVertex();
  }
  {
    SCOPED_TRACE(kMesh);
    numerics::convexMeshThroughItsEdgesAndFaces();
  }
}

TEST(A4_2_HardCases, FlatBoxesPlanesSharedEdgesAndClosedMeshes) { allCases("bvh"); }
TEST(A4_3_HardCases, FlatBoxesPlanesSharedEdgesAndClosedMeshes) { allCases("kdtree"); }
TEST(A4_4_HardCases, FlatBoxesPlanesSharedEdgesAndClosedMeshes) { allCases("octree"); }
TEST(A4_5_HardCases, FlatBoxesPlanesSharedEdgesAndClosedMeshes) { allCases("bsp"); }

}  // namespace
}  // namespace ll
