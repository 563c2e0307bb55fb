// Hard cases for every accelerator: rays parallel to a triangle's plane or
// lying in it, and axis-parallel rays through the slab tests of flat boxes --
// directions with zero (and negative zero) components, so 1/dir is +-inf and
// an origin exactly on a box's face gives 0 * inf. Each ray has an exact answer.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "numerics/numerics_support.h"

namespace ll::numerics {
namespace {

struct Expected {
  Ray ray;
  uint32_t prim = Hit::kNone;  // kNone: must miss
  float t = 0.0f;
  bool onEdge = false;  // through a triangle's edge or vertex (Embree may decide it either way)
  std::string what;
  float tolerance = 0.0f;  // on t: 0 = exactly
};

void expectAnswers(const Geometry& g, const std::vector<Expected>& cases) {
  for (const BuiltAccelerator& a : everyAccelerator(g)) {
    SCOPED_TRACE(a.name);
    QueryCounters counters;
    for (const Expected& e : cases) {
      if (e.onEdge && !a.exactOnEdges()) continue;
      Hit hit;
      const bool found = a.accel->intersect(e.ray, hit, counters);
      const bool occluded = a.accel->occluded(e.ray, counters);
      if (e.prim == Hit::kNone) {
        EXPECT_FALSE(found) << e.what << ": hit primitive " << hit.prim << " at t = " << hit.t;
        EXPECT_FALSE(occluded) << e.what;
        continue;
      }
      ASSERT_TRUE(found) << e.what;
      EXPECT_TRUE(occluded) << e.what;
      EXPECT_EQ(hit.prim, e.prim) << e.what;
      EXPECT_NEAR(hit.t, e.t, e.tolerance) << e.what;
    }
  }
}

// The wall x = 5 (triangles 1 and 2 of the plane test, |y|, |z| < 10) as the ray's expected hit, in double.
Expected wallAnswer(const Ray& r, const std::string& what) {
  const double t = (5.0 - static_cast<double>(r.origin.x)) / static_cast<double>(r.dir.x);
  const Vec3 p = r.at(static_cast<float>(t));
  Expected e{r, (p.y + 10.0f >= p.z + 10.0f) ? 1u : 2u, static_cast<float>(t), false, what};
  return e;
}

TEST(Numerics_Plane, RaysParallelToOrInATrianglesPlaneMissItAndStillFindTheWallBehind) {
  // A tilted triangle in the plane z = x / 4 and a wall at x = 5. Every coordinate below is a small dyadic
  // number, so "in the plane" and "parallel" hold exactly in float, not just to rounding.
  Geometry g;
  addTriangle(g, Vec3(-1.0f, -1.0f, -0.25f), Vec3(1.0f, -1.0f, 0.25f), Vec3(0.0f, 1.0f, 0.0f));
  addQuad(g, Vec3(5.0f, -10.0f, -10.0f), Vec3(0.0f, 20.0f, 0.0f), Vec3(0.0f, 0.0f, 20.0f));
  const Vec3 inside(0.0f, -0.5f, 0.0f);  // a point of the triangle
  std::vector<Expected> cases;
  for (const Vec3& d : {Vec3(1.0f, 0.5f, 0.25f), Vec3(1.0f, -0.5f, 0.25f), Vec3(1.0f, 0.0f, 0.25f), Vec3(2.0f, 1.0f, 0.5f)}) {
    // In the plane, through the triangle's inside (and through its vertex p2 and along its edge p0-p1).
    cases.push_back(wallAnswer(ray(inside - 4.0f * d, d), "in the plane"));
    cases.push_back(wallAnswer(ray(Vec3(0.0f, 1.0f, 0.0f) - 4.0f * d, d), "in the plane through a vertex"));
    // Parallel to the plane, just above and below it.
    for (float h : {0x1p-10f, -0x1p-10f, 0x1p-20f, -0x1p-20f})
      cases.push_back(wallAnswer(ray(inside + Vec3(0.0f, 0.0f, h) - 4.0f * d, d), "parallel at " + std::to_string(h)));
    // In the plane, away from the wall: nothing at all.
    cases.push_back({ray(inside - 4.0f * d, -d), Hit::kNone, 0.0f, false, "in the plane, backwards"});
  }
  const Vec3 edge(1.0f, 0.0f, 0.25f);  // along the edge p0-p1, lying on it
  cases.push_back(wallAnswer(ray(Vec3(-1.0f, -1.0f, -0.25f) - 4.0f * edge, edge), "along the edge p0-p1"));
  expectAnswers(g, cases);
}

// Unit squares (two triangles each) in the planes x = 3, y = 3, z = 3, spanning [0, 1] in the other two
// axes, plus a big one behind in z = 8 so boxes nest. Flat boxes: every square's box has zero thickness.
Geometry flatSquares() {
  Geometry g;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 o(0.0f), e1(0.0f), e2(0.0f);
    o[axis] = 3.0f;
    e1[(axis + 1) % 3] = 1.0f;
    e2[(axis + 2) % 3] = 1.0f;
    addQuad(g, o, e1, e2);
  }
  addQuad(g, Vec3(-20.0f, -20.0f, 8.0f), Vec3(40.0f, 0.0f, 0.0f), Vec3(0.0f, 40.0f, 0.0f));  // triangles 6, 7
  return g;
}

TEST(Numerics_Slab, AxisParallelRaysThroughFlatBoxesAndAlongTheirFaces) {
  const Geometry g = flatSquares();
  const float below = -std::nextafter(0.0f, 1.0f) * 1024.0f, above = 1.0f + 1.2e-7f * 8.0f;  // just outside [0, 1]
  std::vector<Expected> cases;
  for (int axis = 0; axis < 3; ++axis) {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    for (float sign : {1.0f, -1.0f})
      for (float a : {0.0f, 0.25f, 0.5f, 1.0f, below, above})
        for (float b : {0.0f, 0.5f, 0.75f, 1.0f, below, above}) {
          Vec3 o(0.0f), d(0.0f);
          o[axis] = 3.0f - 2.0f * sign;  // t = 2 to the square
          o[i] = a;
          o[j] = b;
          d[axis] = sign;
          d[i] = -0.0f;  // negative zero: 1/d = -inf
          const bool inside = a >= 0.0f && a <= 1.0f && b >= 0.0f && b <= 1.0f;
          // On an edge, the diagonal a == b, or a few ulps beside an edge: Embree may decide these either way.
          const auto nearEdge = [&](float x) { return x == 0.0f || x == 1.0f || x == below || x == above; };
          const bool edge = nearEdge(a) || nearEdge(b) || a == b;
          // Which of the square's two triangles: (o, o+e1, o+e1+e2) holds a >= b.
          uint32_t prim = static_cast<uint32_t>(2 * axis) + (a >= b ? 0u : 1u);
          float t = 2.0f;
          if (!inside) {
            // Past the square: along +z the big square at z = 8 (t = 5 + 2 from o.z = 1); otherwise nothing.
            const bool reachesBig = axis == 2 && sign > 0.0f;
            prim = reachesBig ? 6u + (o.x - (-20.0f) >= o.y - (-20.0f) ? 0u : 1u) : Hit::kNone;
            t = 7.0f;
          }
          cases.push_back({ray(o, d), prim, t, edge,
                           "axis " + std::to_string(axis) + " sign " + std::to_string(sign) + " at (" +
                               std::to_string(a) + ", " + std::to_string(b) + ")"});
        }
    // Lying in the square's own plane (its flat box's faces: 0 * inf in the slab test): it misses the
    // square. In the plane y = 3 it runs along +z from (0.5, 3, -1.5) to the big square at t = 9.5.
    Vec3 o(0.5f), d(0.0f);
    o[axis] = 3.0f;
    d[i] = 1.0f;
    cases.push_back({ray(o - 2.0f * d, d), axis == 1 ? 7u : Hit::kNone, 9.5f, false,
                     "in the plane of square " + std::to_string(axis)});
  }
  // Along +z in the plane x = 3, starting on the x-square's edge z = 1: edge-on to it, on to the big square.
  cases.push_back({ray(Vec3(3.0f, 0.5f, 1.0f), Vec3(0.0f, 0.0f, 1.0f)), 6u, 7.0f, false, "along the x-square's face"});
  expectAnswers(g, cases);
}

}  // namespace
}  // namespace ll::numerics
