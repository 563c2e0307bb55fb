// The framework's reference primitive tests (watertight triangles, careful
// spheres) and the brute-force accelerator `none`, against closed-form answers
// computed independently here in double precision.
#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_support.h"

#include "accel/accelerator.h"
#include "accel/ray_sphere.h"
#include "accel/ray_triangle.h"
#include "modules/registry.h"
#include "scene/geometry.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

using DVec3 = glm::dvec3;

using testing_support::makeRay;

struct TriHit {
  bool hit = false;
  float t = 0.0f, b1 = 0.0f, b2 = 0.0f;
};

TriHit triangle(const Ray& ray, Vec3 p0, Vec3 p1, Vec3 p2) {
  TriHit h;
  h.hit = intersectTriangle(WatertightRay(ray), p0, p1, p2, ray.tmin, ray.tmax, h.t, h.b1, h.b2);
  return h;
}

std::unique_ptr<Accelerator> bruteForce(const Geometry& g) {
  const AcceleratorInfo& info = findAccelerator("none");
  const ParamSet params("accelerator 'none'", info.params);
  return buildAccelerator(info, params, g);
}

// --- Triangles ---------------------------------------------------------------------

TEST(RayTriangle, HitAlongMinusZKnownTAndBarycentrics) {
  const Vec3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0);
  const TriHit h = triangle(makeRay({0.25f, 0.5f, 5.0f}, {0, 0, -1}), p0, p1, p2);
  ASSERT_TRUE(h.hit);
  EXPECT_FLOAT_EQ(h.t, 5.0f);
  EXPECT_FLOAT_EQ(h.b1, 0.25f);  // weight of p1 = x
  EXPECT_FLOAT_EQ(h.b2, 0.5f);   // weight of p2 = y
}

TEST(RayTriangle, GeneralTriangleAndObliqueRay) {
  // Hit point P = 0.2 p0 + 0.5 p1 + 0.3 p2, ray from P + 3 d travelling -2 d: t = 1.5.
  const Vec3 p0(1.0f, -2.0f, 0.5f), p1(3.0f, 1.0f, -1.0f), p2(-1.0f, 2.0f, 2.0f);
  const Vec3 P = 0.2f * p0 + 0.5f * p1 + 0.3f * p2;
  const Vec3 d = glm::normalize(Vec3(0.3f, -0.4f, 1.0f));
  const TriHit h = triangle(makeRay(P + 3.0f * d, -2.0f * d), p0, p1, p2);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.t, 1.5f, 1e-5f);
  EXPECT_NEAR(h.b1, 0.5f, 1e-5f);
  EXPECT_NEAR(h.b2, 0.3f, 1e-5f);
  // Both faces: the same triangle from the other side.
  const TriHit back = triangle(makeRay(P - 3.0f * d, 2.0f * d), p0, p1, p2);
  ASSERT_TRUE(back.hit);
  EXPECT_NEAR(back.t, 1.5f, 1e-5f);
  EXPECT_NEAR(back.b1, 0.5f, 1e-5f);
  EXPECT_NEAR(back.b2, 0.3f, 1e-5f);
}

TEST(RayTriangle, MissesOutsideEachEdge) {
  const Vec3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0);
  for (Vec3 o : {Vec3(0.6f, 0.6f, 5.0f), Vec3(-0.1f, 0.5f, 5.0f), Vec3(0.5f, -0.1f, 5.0f), Vec3(2.0f, 2.0f, 5.0f)})
    EXPECT_FALSE(triangle(makeRay(o, {0, 0, -1}), p0, p1, p2).hit) << o.x << "," << o.y;
  // Parallel to the plane, in the plane and beside it.
  EXPECT_FALSE(triangle(makeRay({0.2f, 0.2f, 1.0f}, {1, 0, 0}), p0, p1, p2).hit);
  EXPECT_FALSE(triangle(makeRay({-1.0f, 0.2f, 0.0f}, {1, 0, 0}), p0, p1, p2).hit);
}

TEST(RayTriangle, RespectsTminAndTmax) {
  const Vec3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0);
  const Vec3 o(0.2f, 0.2f, 5.0f), d(0, 0, -1);
  EXPECT_TRUE(triangle(makeRay(o, d, 0.0f, 5.1f), p0, p1, p2).hit);
  EXPECT_FALSE(triangle(makeRay(o, d, 0.0f, 4.9f), p0, p1, p2).hit);
  EXPECT_FALSE(triangle(makeRay(o, d, 5.1f), p0, p1, p2).hit);
  EXPECT_TRUE(triangle(makeRay(o, d, 4.9f), p0, p1, p2).hit);
  // Behind the origin.
  EXPECT_FALSE(triangle(makeRay({0.2f, 0.2f, -5.0f}, d), p0, p1, p2).hit);
  // t is in units of |dir|.
  const TriHit h = triangle(makeRay(o, {0, 0, -4}), p0, p1, p2);
  ASSERT_TRUE(h.hit);
  EXPECT_FLOAT_EQ(h.t, 1.25f);
}

// Rays aimed at (or near) the triangle's points and along its line.
void expectNeverHit(const std::array<Vec3, 3>& tri, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    const float s = 0.5f + 0.5f * u(gen);
    const Vec3 target = tri[0] + s * (tri[1] - tri[0]) + s * 0.3f * (tri[2] - tri[0]);
    const Vec3 origin = target + Vec3(u(gen), u(gen), u(gen)) * 4.0f;
    ASSERT_FALSE(triangle(makeRay(origin, target - origin), tri[0], tri[1], tri[2]).hit) << "ray " << i;
  }
  const Vec3 along = tri[1] - tri[0] + tri[2] - tri[0];
  EXPECT_FALSE(triangle(makeRay(tri[0] - along, along), tri[0], tri[1], tri[2]).hit);
}

TEST(RayTriangle, TrianglesWithRepeatedVerticesNeverHit) {
  const Vec3 a(0.1f, 0.2f, 0.3f), b(1.1f, 1.7f, 1.3f);
  const std::vector<std::array<Vec3, 3>> degenerate = {{a, a, b}, {a, b, b}, {b, a, b}, {a, a, a}};
  for (size_t k = 0; k < degenerate.size(); ++k) {
    SCOPED_TRACE("triangle " + std::to_string(k));
    expectNeverHit(degenerate[k], 17u + static_cast<unsigned>(k));
  }
}

// Three distinct, exactly collinear vertices (cross(p1-p0, p2-p0) == 0 in
// float): the sheared edge functions round to a sliver, and ~13 % of these rays
// used to hit, with a NaN normal from Scene::surfacePoint. tests/numerics has
// the same through every accelerator.
TEST(RayTriangle, CollinearTrianglesNeverHit) {
  const Vec3 a(0.125f, 0.25f, 0.375f), b(1.125f, 1.75f, 1.375f), c(2.125f, 3.25f, 2.375f);
  ASSERT_EQ(glm::cross(b - a, c - a), Vec3(0.0f));  // exactly zero area in float
  expectNeverHit({a, b, c}, 17u);
  expectNeverHit({b, c, a}, 18u);
}

TEST(RayTriangle, AxisParallelRaysWithZeroComponents) {
  // A triangle facing each axis, rays along +-x, +-y, +-z (two exactly-zero components).
  for (int axis = 0; axis < 3; ++axis) {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    Vec3 p0(0.0f), p1(0.0f), p2(0.0f);
    p1[i] = 2.0f;
    p2[j] = 2.0f;
    for (float sign : {1.0f, -1.0f}) {
      Vec3 dir(0.0f), origin(0.0f);
      dir[axis] = sign;
      origin[axis] = -3.0f * sign;
      origin[i] = 0.5f;
      origin[j] = 0.75f;
      const TriHit h = triangle(makeRay(origin, dir), p0, p1, p2);
      ASSERT_TRUE(h.hit) << axis << " " << sign;
      EXPECT_FLOAT_EQ(h.t, 3.0f);
      EXPECT_FLOAT_EQ(h.b1, 0.25f);
      EXPECT_FLOAT_EQ(h.b2, 0.375f);
      origin[i] = 1.5f;  // b1 + b2 = 0.75 + 0.375 > 1
      EXPECT_FALSE(triangle(makeRay(origin, dir), p0, p1, p2).hit);
    }
  }
}

// A closed fan of triangles around `centre`: rim points rim[0..n-1], triangle k =
// (centre, rim[k], rim[k+1 mod n]).
Geometry fanGeometry(const Vec3& centre, const std::vector<Vec3>& rim) {
  Geometry g;
  g.positions.push_back(centre);
  for (const Vec3& p : rim) g.positions.push_back(p);
  const auto n = static_cast<unsigned>(rim.size());
  for (unsigned k = 0; k < n; ++k) {
    g.triangles.emplace_back(0u, 1u + k, 1u + (k + 1) % n);
    g.triangleObject.push_back(0);
  }
  return g;
}

// Shoots rays from `origins` exactly through points on the fan's shared edges
// (centre to rim vertex) and through the centre: none may miss.
void expectNoCracks(const Geometry& g, const std::vector<Vec3>& origins, int pointsPerEdge, bool planar,
                    int& rays) {
  const auto accel = bruteForce(g);
  QueryCounters counters;
  const Vec3 centre = g.positions[0];
  for (const Vec3& o : origins) {
    for (size_t k = 1; k < g.positions.size(); ++k) {
      const Vec3 e = g.positions[k] - centre;
      for (int s = 0; s <= pointsPerEdge; ++s) {
        // s = 0 is the shared centre vertex; the rim end (s = pointsPerEdge + 1) is a boundary.
        const float f = static_cast<float>(s) / static_cast<float>(pointsPerEdge + 1);
        const Vec3 target = centre + f * e;
        const Ray ray = makeRay(o, target - o);
        Hit hit;
        ++rays;
        ASSERT_TRUE(accel->intersect(ray, hit, counters))
            << "crack: ray from (" << o.x << "," << o.y << "," << o.z << ") through edge " << k << " at " << f;
        if (planar) {
          ASSERT_NEAR(hit.t, 1.0f, 1e-4f);
          // The hit triangle is one of the two adjacent to the edge (or any at the centre).
          const auto tri = g.triangles[hit.prim];
          if (s > 0) {
            ASSERT_TRUE(tri.y == k || tri.z == k) << "edge " << k << " hit triangle " << hit.prim;
          }
        } else {
          ASSERT_LE(hit.t, 1.0f + 1e-4f);
        }
        ASSERT_TRUE(accel->occluded(ray, counters));
      }
    }
  }
}

TEST(RayTriangle, WatertightFanNeverLeaksThroughSharedEdgesOrVertex) {
  std::mt19937 gen(2024);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  // A planar fan in a tilted plane with irregular angles (inexact float coordinates).
  const Vec3 centre(0.137f, -0.291f, 0.453f);
  const Vec3 n = glm::normalize(Vec3(0.3f, 0.8f, 0.5f));
  const Frame frame(n);
  const std::vector<float> angles = {0.1f, 0.9f, 1.7f, 2.2f, 3.3f, 4.1f, 5.0f, 5.7f};
  std::vector<Vec3> rim;
  for (float a : angles) rim.push_back(centre + 1.3f * (std::cos(a) * frame.s + std::sin(a) * frame.t));
  const Geometry planar = fanGeometry(centre, rim);
  // A non-planar fan: a tent with its apex raised towards the viewers. Its
  // faces slope by at most ~15 degrees, less than any viewing elevation below,
  // so no shared edge is a silhouette (where a ray may legitimately pass).
  std::vector<Vec3> tentRim;
  for (size_t k = 0; k < angles.size(); ++k)
    tentRim.push_back(rim[k] - (0.1f + 0.02f * static_cast<float>(k)) * n);
  const Geometry tent = fanGeometry(centre, tentRim);

  std::vector<Vec3> origins;
  while (origins.size() < 20) {
    const Vec3 d(u(gen), u(gen), u(gen));
    if (glm::length(d) > 1.0f || glm::length(d) < 0.1f) continue;
    const Vec3 dir = glm::normalize(d);
    if (glm::dot(dir, n) < 0.7f) continue;  // viewers well above the fans
    origins.push_back(centre + (5.0f + 5.0f * std::abs(u(gen))) * dir);
  }
  int rays = 0;
  expectNoCracks(planar, origins, 60, true, rays);
  expectNoCracks(tent, origins, 60, false, rays);
  EXPECT_GE(rays, 19000);
}

TEST(RayTriangle, WatertightAxisAlignedFanWithAxisParallelRays) {
  // Octagon fan in z = 0 with edges along the axes and diagonals; rays along
  // -z and +z (dir.x = dir.y = 0 exactly) through exact points on the edges.
  std::vector<Vec3> rim;
  for (int k = 0; k < 8; ++k) {
    const float a = static_cast<float>(k) * kPi / 4.0f;
    rim.emplace_back(k % 2 == 0 ? std::round(std::cos(a)) : std::cos(a), k % 2 == 0 ? std::round(std::sin(a)) : std::sin(a), 0.0f);
  }
  const Geometry g = fanGeometry(Vec3(0.0f), rim);
  const auto accel = bruteForce(g);
  QueryCounters counters;
  int rays = 0;
  for (size_t k = 1; k < g.positions.size(); ++k)
    for (int s = 0; s < 200; ++s) {
      const Vec3 p = (static_cast<float>(s) / 200.0f) * g.positions[k];
      for (float sign : {-1.0f, 1.0f}) {
        Hit hit;
        const Ray ray = makeRay(Vec3(p.x, p.y, -3.0f * sign), Vec3(0.0f, 0.0f, sign));
        ++rays;
        ASSERT_TRUE(accel->intersect(ray, hit, counters)) << k << " " << s << " " << sign;
        ASSERT_NEAR(hit.t, 3.0f, 1e-6f);
      }
    }
  EXPECT_EQ(rays, 8 * 200 * 2);
}

TEST(RayTriangle, ClosedCubeNeverLeaksFromInside) {
  // 12 triangles of a unit cube; rays from interior points towards every
  // vertex and edge midpoint of the cube must hit it at the aimed point.
  Geometry g;
  for (int i = 0; i < 8; ++i)
    g.positions.emplace_back((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f);
  const unsigned faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    g.triangles.emplace_back(f[0], f[1], f[2]);
    g.triangles.emplace_back(f[0], f[2], f[3]);
    g.triangleObject.push_back(0);
    g.triangleObject.push_back(0);
  }
  const auto accel = bruteForce(g);
  std::vector<Vec3> targets = g.positions;
  for (int i = 0; i < 8; ++i)
    for (int j = i + 1; j < 8; ++j)
      if (glm::length(g.positions[static_cast<size_t>(i)] - g.positions[static_cast<size_t>(j)]) < 2.5f)
        targets.push_back(0.5f * (g.positions[static_cast<size_t>(i)] + g.positions[static_cast<size_t>(j)]));
  std::mt19937 gen(5);
  std::uniform_real_distribution<float> u(-0.9f, 0.9f);
  QueryCounters counters;
  for (int i = 0; i < 100; ++i) {
    const Vec3 o = i == 0 ? Vec3(0.0f) : Vec3(u(gen), u(gen), u(gen));
    for (const Vec3& target : targets) {
      Hit hit;
      ASSERT_TRUE(accel->intersect(makeRay(o, target - o), hit, counters)) << i;
      ASSERT_NEAR(hit.t, 1.0f, 1e-5f);
    }
  }
}

// --- Spheres -----------------------------------------------------------------------

bool sphere(const Ray& ray, Vec3 c, float r, float& t) { return intersectSphere(ray, c, r, ray.tmin, ray.tmax, t); }

TEST(RaySphere, HitFromOutsideKnownT) {
  float t = 0.0f;
  ASSERT_TRUE(sphere(makeRay({0, 0, 5}, {0, 0, -1}), Vec3(0.0f), 1.0f, t));
  EXPECT_FLOAT_EQ(t, 4.0f);
  ASSERT_TRUE(sphere(makeRay({0.6f, 0, 5}, {0, 0, -1}), Vec3(0.0f), 1.0f, t));
  EXPECT_NEAR(t, 4.2f, 1e-6f);  // 5 - sqrt(1 - 0.36)
  ASSERT_TRUE(sphere(makeRay({0, 0, 5}, {0, 0, -2}), Vec3(0.0f), 1.0f, t));
  EXPECT_FLOAT_EQ(t, 2.0f);  // t in units of |dir|
  ASSERT_TRUE(sphere(makeRay({3, 4, 5}, {0, -1, 0}), Vec3(3, -2, 5), 2.0f, t));
  EXPECT_FLOAT_EQ(t, 4.0f);
}

TEST(RaySphere, MissesAndBehind) {
  float t = -7.0f;
  EXPECT_FALSE(sphere(makeRay({1.5f, 0, 5}, {0, 0, -1}), Vec3(0.0f), 1.0f, t));
  EXPECT_FALSE(sphere(makeRay({0, 0, 5}, {0, 0, 1}), Vec3(0.0f), 1.0f, t));  // sphere behind
  EXPECT_FALSE(sphere(makeRay({0, 0, 5}, {1, 0, 0}), Vec3(0.0f), 1.0f, t));
  EXPECT_EQ(t, -7.0f) << "t must not be written on a miss";
}

TEST(RaySphere, FromInsideReturnsTheExit) {
  float t = 0.0f;
  ASSERT_TRUE(sphere(makeRay({0, 0, 0}, {1, 0, 0}), Vec3(0.0f), 1.0f, t));
  EXPECT_FLOAT_EQ(t, 1.0f);
  ASSERT_TRUE(sphere(makeRay({0.5f, 0, 0}, {1, 0, 0}), Vec3(0.0f), 1.0f, t));
  EXPECT_FLOAT_EQ(t, 0.5f);
  ASSERT_TRUE(sphere(makeRay({0.5f, 0, 0}, {-1, 0, 0}), Vec3(0.0f), 1.0f, t));
  EXPECT_FLOAT_EQ(t, 1.5f);
  ASSERT_TRUE(sphere(makeRay({0, 0.6f, 0}, {0, 0, 1}), Vec3(0.0f), 1.0f, t));
  EXPECT_NEAR(t, 0.8f, 1e-6f);
}

TEST(RaySphere, RespectsTminAndTmax) {
  float t = 0.0f;
  const Vec3 o(0, 0, 5), d(0, 0, -1);
  EXPECT_FALSE(sphere(makeRay(o, d, 0.0f, 3.9f), Vec3(0.0f), 1.0f, t));
  ASSERT_TRUE(sphere(makeRay(o, d, 4.5f), Vec3(0.0f), 1.0f, t));
  EXPECT_FLOAT_EQ(t, 6.0f);  // near root excluded: the far one
  EXPECT_FALSE(sphere(makeRay(o, d, 6.5f), Vec3(0.0f), 1.0f, t));
  EXPECT_FALSE(sphere(makeRay(o, d, 4.5f, 5.5f), Vec3(0.0f), 1.0f, t));
}

// The exact (double) perpendicular distance of `c` from the ray's line, and the near root.
struct SphereRef {
  double distance, tNear, tFar;
};
SphereRef sphereRef(const Ray& ray, const DVec3& c, double r) {
  const DVec3 o(ray.origin), d(ray.dir);
  const double a = glm::dot(d, d);
  const double tc = glm::dot(c - o, d) / a;
  const double dist = glm::length(o + tc * d - c);
  const double half = std::sqrt(std::max(0.0, r * r - dist * dist) / a);
  return {dist, tc - half, tc + half};
}

TEST(RaySphere, FarAwaySphereKeepsPrecision) {
  // Centre 1e5 away, radius 1: naive b^2 - c loses every digit of the
  // discriminant in float. Rays at offsets h from the axis, with near-tangent ones.
  const Vec3 c(1e5f, 0.0f, 0.0f);
  int hits = 0, misses = 0;
  for (int i = -150; i <= 150; ++i) {
    const float h = static_cast<float>(i) / 100.0f;  // -1.5 .. 1.5
    for (Vec3 origin : {Vec3(0.0f), Vec3(3.0f, -2.0f, 1.0f)}) {
      const Vec3 aim(1e5f, h, 0.37f * h);
      const Ray ray = makeRay(origin, glm::normalize(aim - origin));
      const SphereRef ref = sphereRef(ray, DVec3(c), 1.0);
      float t = 0.0f;
      const bool hit = sphere(ray, c, 1.0f, t);
      if (std::abs(ref.distance - 1.0) < 0.01) continue;  // too close to tangent to demand a side
      ASSERT_EQ(hit, ref.distance < 1.0) << "h = " << h << " distance " << ref.distance;
      if (!hit) {
        ++misses;
        continue;
      }
      ++hits;
      EXPECT_NEAR(static_cast<double>(t), ref.tNear, 1e-3 * ref.tNear) << h;
      // Much better than 1e-3: the hit point is on the sphere to a few float ulps of 1e5.
      const DVec3 p = DVec3(ray.origin) + static_cast<double>(t) * DVec3(ray.dir);
      EXPECT_NEAR(glm::length(p - DVec3(c)), 1.0, 0.05) << h;
    }
  }
  EXPECT_GT(hits, 200);
  EXPECT_GT(misses, 100);
}

TEST(RaySphere, TinyAndHugeSpheres) {
  float t = 0.0f;
  // Radius 1e-3 at distance 100.
  ASSERT_TRUE(sphere(makeRay({0, 0, 0}, {0, 0, 1}), Vec3(0.0005f, 0.0f, 100.0f), 1e-3f, t));
  EXPECT_NEAR(t, 100.0f - std::sqrt(1e-6f - 0.0005f * 0.0005f), 1e-4f);
  EXPECT_FALSE(sphere(makeRay({0, 0, 0}, {0, 0, 1}), Vec3(0.0011f, 0.0f, 100.0f), 1e-3f, t));
  // A sphere of radius 1e4 seen from just outside (a "ground" sphere).
  ASSERT_TRUE(sphere(makeRay({0, 1.0f, 0}, {0, -1, 0}), Vec3(0.0f, -1e4f, 0.0f), 1e4f, t));
  EXPECT_NEAR(t, 1.0f, 1e-3f);
}

// --- Brute force against an independent double-precision reference ----------------

struct RefHit {
  bool hit = false;
  bool ambiguous = false;
  double t = 0.0;
  uint32_t prim = Hit::kNone;
  double b1 = 0.0, b2 = 0.0;
};

// Closest hit in double with t > 0, computed without the framework's code:
// plane + barycentrics for triangles, the quadratic for spheres. A ray is
// "ambiguous" if any primitive is within a small margin of hit/miss or two
// hits are nearly equally close; such rays are skipped.
RefHit reference(const Geometry& g, const Ray& ray) {
  const DVec3 o(ray.origin), d(ray.dir);
  RefHit best;
  best.t = 1e300;
  double second = 1e300;
  auto consider = [&](double t, uint32_t prim, double b1, double b2) {
    if (t < best.t) {
      second = best.t;
      best.t = t;
      best.prim = prim;
      best.b1 = b1;
      best.b2 = b2;
      best.hit = true;
    } else {
      second = std::min(second, t);
    }
  };
  for (uint32_t p = 0; p < g.primitiveCount(); ++p) {
    if (g.isTriangle(p)) {
      const glm::uvec3 tri = g.triangles[p];
      const DVec3 p0(g.positions[tri.x]), p1(g.positions[tri.y]), p2(g.positions[tri.z]);
      const DVec3 n = glm::cross(p1 - p0, p2 - p0);
      const double denom = glm::dot(n, d);
      if (std::abs(denom) < 1e-12 * glm::length(n) * glm::length(d)) continue;
      const double t = glm::dot(n, p0 - o) / denom;
      const DVec3 x = o + t * d;
      const double area2 = glm::dot(n, n);
      const double b1 = glm::dot(glm::cross(p2 - x, p0 - x), n) / area2;  // weight of p1
      const double b2 = glm::dot(glm::cross(p0 - x, p1 - x), n) / area2;  // weight of p2
      const double b0 = 1.0 - b1 - b2;
      const double margin = std::min(b0, std::min(b1, b2));
      if (std::abs(margin) < 1e-4 || std::abs(t) < 1e-4) best.ambiguous = true;
      if (margin > 0.0 && t > 0.0) consider(t, p, b1, b2);
    } else {
      const Sphere& s = g.spheres[p - g.triangleCount()];
      const double r = s.radius;
      const DVec3 f = o - DVec3(s.center);
      const double a = glm::dot(d, d), b = glm::dot(f, d), c = glm::dot(f, f) - r * r;
      const double disc = b * b - a * c;
      if (std::abs(disc) < 1e-4 * a * r * r) best.ambiguous = true;
      if (disc < 0.0) continue;
      const double t0 = (-b - std::sqrt(disc)) / a, t1 = (-b + std::sqrt(disc)) / a;
      if (std::abs(t0) < 1e-4 || std::abs(t1) < 1e-4) best.ambiguous = true;
      if (t0 > 0.0)
        consider(t0, p, 0.0, 0.0);
      else if (t1 > 0.0)
        consider(t1, p, 0.0, 0.0);
    }
  }
  if (best.hit && second - best.t < 1e-3 * std::max(1.0, best.t)) best.ambiguous = true;
  return best;
}

void compareWithReference(const Geometry& g, float extent, int rayCount, unsigned seed) {
  const auto accel = bruteForce(g);
  std::mt19937 gen(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::uniform_int_distribution<uint32_t> pick(0, g.primitiveCount() - 1);
  const Bounds3 bounds = g.sceneBounds();
  int checked = 0, hits = 0;
  QueryCounters counters;
  for (int i = 0; i < rayCount; ++i) {
    const Vec3 origin = bounds.center() + extent * Vec3(u(gen), u(gen), u(gen));
    Vec3 dir;
    if (i % 2 == 0) {
      dir = Vec3(u(gen), u(gen), u(gen));  // a random direction
    } else {
      // Aim near a random primitive so that most rays hit something.
      const Bounds3 b = g.bounds(pick(gen));
      dir = b.center() + 0.6f * b.extent() * Vec3(u(gen), u(gen), u(gen)) - origin;
    }
    if (glm::length(dir) < 1e-3f) continue;
    const Ray ray = makeRay(origin, dir);
    const RefHit ref = reference(g, ray);
    if (ref.ambiguous) continue;
    ++checked;
    Hit hit;
    const bool found = accel->intersect(ray, hit, counters);
    ASSERT_EQ(found, ref.hit) << "ray " << i;
    ASSERT_EQ(accel->occluded(ray, counters), ref.hit) << "ray " << i;
    if (!found) continue;
    ++hits;
    ASSERT_EQ(hit.prim, ref.prim) << "ray " << i;
    ASSERT_NEAR(static_cast<double>(hit.t), ref.t, 1e-4 * std::max(1.0, ref.t)) << "ray " << i;
    if (g.isTriangle(hit.prim)) {
      ASSERT_NEAR(static_cast<double>(hit.b1), ref.b1, 1e-4) << "ray " << i;
      ASSERT_NEAR(static_cast<double>(hit.b2), ref.b2, 1e-4) << "ray " << i;
    }
    // tmax just before the closest hit: nothing at all.
    Ray shorter = ray;
    shorter.tmax = static_cast<float>(ref.t * 0.999);
    Hit h2;
    ASSERT_FALSE(accel->intersect(shorter, h2, counters)) << "ray " << i;
    ASSERT_FALSE(accel->occluded(shorter, counters)) << "ray " << i;
  }
  EXPECT_GT(checked, rayCount * 9 / 10);
  EXPECT_GT(hits, checked / 3);
  EXPECT_LT(hits, checked);
}

TEST(BruteForce, AgreesWithClosedFormOnBuiltScene) {
  Geometry g;
  auto addQuad = [&](Vec3 a, Vec3 b, Vec3 c, Vec3 d, uint32_t object) {
    const auto base = static_cast<unsigned>(g.positions.size());
    for (const Vec3& p : {a, b, c, d}) g.positions.push_back(p);
    g.triangles.emplace_back(base, base + 1, base + 2);
    g.triangles.emplace_back(base, base + 2, base + 3);
    g.triangleObject.push_back(object);
    g.triangleObject.push_back(object);
  };
  addQuad({-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, {-3, 0, -3}, 0);                  // floor
  addQuad({-2, 0.5f, -2}, {1, 0.2f, -2.5f}, {1.5f, 2.5f, -2}, {-2, 2.8f, -1.5f}, 1);  // tilted wall
  g.triangles.emplace_back(0u, 5u, 6u);  // a triangle across the scene
  g.triangleObject.push_back(2);
  g.spheres = {Sphere{{-0.8f, 0.7f, 0.0f}, 0.7f}, Sphere{{0.9f, 0.6f, 0.6f}, 0.6f},
               Sphere{{0.3f, 1.5f, 0.2f}, 0.25f}, Sphere{{1.0f, 0.8f, 0.4f}, 0.3f},  // overlaps the second
               Sphere{{0.0f, 2.0f, -1.0f}, 0.05f}};
  g.sphereObject = {3, 4, 5, 6, 7};
  compareWithReference(g, 4.0f, 4000, 99);
}

TEST(BruteForce, AgreesWithClosedFormOnBundledScene) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/tests/two_spheres_materials.json");
  ASSERT_EQ(scene.geometry.triangleCount(), 2u);
  ASSERT_EQ(scene.geometry.spheres.size(), 2u);
  compareWithReference(scene.geometry, 3.5f, 3000, 7);
}

TEST(BruteForce, CountsPrimitivesAndReportsEmptyScene) {
  Geometry g;
  g.spheres = {Sphere{{0, 0, 0}, 1.0f}, Sphere{{0, 0, -5}, 1.0f}};
  g.sphereObject = {0, 1};
  const auto accel = bruteForce(g);
  QueryCounters counters;
  Hit hit;
  ASSERT_TRUE(accel->intersect(makeRay({0, 0, 5}, {0, 0, -1}), hit, counters));
  EXPECT_EQ(hit.prim, 0u);
  EXPECT_FLOAT_EQ(hit.t, 4.0f);
  EXPECT_EQ(counters.primitivesTested, 2u);
  // From between the spheres, looking at the far one.
  ASSERT_TRUE(accel->intersect(makeRay({0, 0, -2.5f}, {0, 0, -1}), hit, counters));
  EXPECT_EQ(hit.prim, 1u);
  EXPECT_FLOAT_EQ(hit.t, 1.5f);
  // tmax before the first sphere: nothing.
  EXPECT_FALSE(accel->intersect(makeRay({0, 0, 5}, {0, 0, -1}, 0.0f, 3.0f), hit, counters));
  EXPECT_FALSE(hit.valid());
  EXPECT_FALSE(accel->occluded(makeRay({0, 0, 5}, {0, 0, -1}, 0.0f, 3.0f), counters));

  const Geometry empty;
  const auto none = bruteForce(empty);
  EXPECT_FALSE(none->intersect(makeRay({0, 0, 0}, {1, 0, 0}), hit, counters));
  EXPECT_FALSE(none->occluded(makeRay({0, 0, 0}, {1, 0, 0}), counters));
}

}  // namespace
}  // namespace ll
