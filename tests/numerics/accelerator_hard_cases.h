// The accelerators' hard cases, each with an exact answer: rays parallel to a
// triangle's plane or lying in it; axis-parallel rays through the slab tests
// of flat boxes (directions with zero and negative-zero components, so 1/dir
// is +-inf and an origin on a box's face gives 0 * inf); rays exactly through
// the shared edges and vertex of a fan (never a miss, never a second hit past
// the sheet); rays through a closed mesh's edges (exactly two crossings).
// Each case runs on every accelerator of everyAccelerator() -- all of them in
// tests/numerics, one (OnlyAccelerator) in the graded hard cases of A4.2-A4.5.
#pragma once

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "numerics/numerics_support.h"
#include "render/ray_offset.h"

namespace ll::numerics {

struct Expected {
  Ray ray;
  uint32_t prim = Hit::kNone;  // kNone: must miss
  float t = 0.0f;
  bool onEdge = false;  // through a triangle's edge or vertex (Embree may decide it either way)
  std::string what;
  float tolerance = 0.0f;  // on t: 0 = exactly
};

inline void expectAnswers(const Geometry& g, const std::vector<Expected>& cases) {
  for (const BuiltAccelerator& a : everyAccelerator(g)) {
    SCOPED_TRACE(a.name);
    QueryCounters counters;
    for (const Expected& e : cases) {
      if (e.onEdge && !a.exactOnEdges()) continue;
      Hit hit;
      const bool found = a.accel->intersect(e.ray, hit, counters);
      const bool occluded = a.accel->occluded(e.ray, counters);
      if (e.prim == Hit::kNone) {
        EXPECT_FALSE(found) << e.what << ": should miss, got " << testing_support::describeHit(hit);
        EXPECT_FALSE(occluded) << e.what << ": should miss, but occluded() says blocked";
        continue;
      }
      ASSERT_TRUE(found) << e.what << ": got no hit, expected primitive " << e.prim << " at t = " << e.t;
      EXPECT_TRUE(occluded) << e.what << ": occluded() says free, expected blocked by primitive " << e.prim;
      EXPECT_EQ(hit.prim, e.prim) << e.what;
      EXPECT_NEAR(hit.t, e.t, e.tolerance) << e.what;
    }
  }
}

// The wall x = 5 (triangles 1 and 2 of the plane test, |y|, |z| < 10) as the ray's expected hit, in double.
inline Expected wallAnswer(const Ray& r, const std::string& what) {
  const double t = (5.0 - static_cast<double>(r.origin.x)) / static_cast<double>(r.dir.x);
  const Vec3 p = r.at(static_cast<float>(t));
  Expected e{r, (p.y + 10.0f >= p.z + 10.0f) ? 1u : 2u, static_cast<float>(t), false, what};
  return e;
}

inline void raysParallelToOrInATrianglesPlane() {
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
inline Geometry flatSquares() {
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

inline void axisParallelRaysThroughFlatBoxes() {
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

// A planar fan in a tilted plane with irregular angles (inexact float coordinates).
struct TiltedFan {
  Vec3 centre{0.137f, -0.291f, 0.453f};
  Vec3 normal = glm::normalize(Vec3(0.3f, 0.8f, 0.5f));
  Geometry geometry;
  TiltedFan() {
    const Frame frame(normal);
    std::vector<Vec3> rim;
    for (float a : {0.1f, 0.9f, 1.7f, 2.2f, 3.3f, 4.1f, 5.0f, 5.7f})
      rim.push_back(centre + 1.3f * (std::cos(a) * frame.s + std::sin(a) * frame.t));
    geometry = fan(centre, rim);
  }
};

inline void fanSharedEdgesAndVertex() {
  const TiltedFan f;
  std::mt19937 gen(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<Vec3> origins;
  while (origins.size() < 8) {
    const Vec3 d(u(gen), u(gen), u(gen));
    if (glm::length(d) < 0.1f || glm::dot(glm::normalize(d), f.normal) < 0.5f) continue;
    origins.push_back(f.centre + 6.0f * glm::normalize(d));
  }
  for (const BuiltAccelerator& a : everyAccelerator(f.geometry)) {
    SCOPED_TRACE(a.name);
    QueryCounters counters;
    int rays = 0;
    for (const Vec3& o : origins)
      for (size_t k = 1; k < f.geometry.positions.size(); ++k)
        for (int s = 0; s < 24; ++s) {  // s = 0: the shared centre vertex; then points along edge k
          const Vec3 target = f.centre + (static_cast<float>(s) / 24.0f) * (f.geometry.positions[k] - f.centre);
          const Ray r = ray(o, target - o);
          Hit hit;
          ++rays;
          ASSERT_TRUE(a.accel->intersect(r, hit, counters)) << "a crack at edge " << k << ", point " << s;
          ASSERT_NEAR(hit.t, 1.0f, 1e-5f);
          const glm::uvec3 tri = f.geometry.triangles[hit.prim];
          if (s > 0 && a.exactOnEdges()) {
            ASSERT_TRUE(tri.y == k || tri.z == k) << "edge " << k << " reported by triangle " << hit.prim;
          }
          ASSERT_TRUE(a.accel->occluded(r, counters));
          // Past the sheet: nothing more (no second hit of the neighbour at the same point).
          const Vec3 p = r.at(hit.t);
          const Ray beyond = ray(offsetRayOrigin(p, faceTowards(f.normal, r.dir)), r.dir);
          Hit again;
          ASSERT_FALSE(a.accel->intersect(beyond, again, counters)) << "double hit at edge " << k << ", point " << s;
        }
    EXPECT_EQ(rays, 8 * 8 * 24);
  }
}

// An irregular octahedron around `c`: six vertices on the axes at unequal distances, tilted by a rotation.
inline Geometry octahedron(Vec3 c, std::vector<Vec3>& vertices) {
  const Mat3 rot = Mat3(glm::rotate(Mat4(1.0f), 0.7f, glm::normalize(Vec3(1.0f, 2.0f, 3.0f))));
  const float r[6] = {1.1f, 0.9f, 1.3f, 0.7f, 1.05f, 0.95f};
  vertices.clear();
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      Vec3 v(0.0f);
      v[axis] = side ? -r[2 * axis + side] : r[2 * axis + side];
      vertices.push_back(c + rot * v);
    }
  Geometry g;
  g.positions = vertices;
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz) {
        g.triangles.emplace_back(0u + static_cast<unsigned>(sx), 2u + static_cast<unsigned>(sy),
                                 4u + static_cast<unsigned>(sz));
        g.triangleObject.push_back(0);
      }
  return g;
}

// Rays from outside through each target and the centre `c` of the octahedron, continued past every hit
// from render/ray_offset.h's origin: each must enter at its target (t = 3/4) and cross exactly twice.
inline void expectTwoCrossings(const Geometry& g, const std::vector<Vec3>& v, Vec3 c, const std::vector<Vec3>& targets) {
  for (const BuiltAccelerator& a : everyAccelerator(g)) {
    SCOPED_TRACE(a.name);
    QueryCounters counters;
    for (size_t i = 0; i < targets.size(); ++i) {
      const Vec3 origin = c + 4.0f * (targets[i] - c);
      Ray r = ray(origin, c - origin);
      int crossings = 0;
      float firstT = -1.0f;
      Hit hit;
      while (crossings < 4 && a.accel->intersect(r, hit, counters)) {
        if (crossings == 0) firstT = hit.t;
        ++crossings;
        const glm::uvec3 tri = g.triangles[hit.prim];
        const Vec3 n = glm::normalize(glm::cross(v[tri.y] - v[tri.x], v[tri.z] - v[tri.x]));
        r = ray(offsetRayOrigin(r.at(hit.t), faceTowards(n, r.dir)), r.dir);
        hit = Hit{};
      }
      EXPECT_EQ(crossings, 2) << "target " << i;
      EXPECT_NEAR(firstT, 0.75f, 1e-5f) << "target " << i;
    }
  }
}

inline void convexMeshThroughItsEdgesAndFaces() {
  const Vec3 c(0.31f, -0.17f, 0.23f);
  std::vector<Vec3> v;
  const Geometry g = octahedron(c, v);
  std::vector<Vec3> targets;  // points on every edge (its midpoint, a quarter, a third) and the faces' centroids
  for (const glm::uvec3& t : g.triangles)
    for (int e = 0; e < 3; ++e)
      for (float f : {0.5f, 0.25f, 1.0f / 3.0f}) targets.push_back(v[t[e]] + f * (v[t[(e + 1) % 3]] - v[t[e]]));
  for (const glm::uvec3& t : g.triangles) targets.push_back((v[t.x] + v[t.y] + v[t.z]) / 3.0f);
  expectTwoCrossings(g, v, c, targets);
}

}  // namespace ll::numerics
