// Hard cases for every accelerator: rays parallel to a triangle's plane or
// lying in it, and axis-parallel rays through the slab tests of flat boxes
// (numerics/accelerator_hard_cases.h).
#include <gtest/gtest.h>

#include "numerics/accelerator_hard_cases.h"

namespace ll::numerics {
namespace {

TEST(Numerics_Plane, RaysParallelToOrInATrianglesPlaneMissItAndStillFindTheWallBehind) {
  raysParallelToOrInATrianglesPlane();
}

TEST(Numerics_Slab, AxisParallelRaysThroughFlatBoxesAndAlongTheirFaces) { axisParallelRaysThroughFlatBoxes(); }

}  // namespace
}  // namespace ll::numerics
