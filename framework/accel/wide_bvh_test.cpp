// Accelerator `bvh4` (the 4-wide BVH): the same hits as brute force, bit for
// bit (t, primitive, barycentrics), on random rays, axis-parallel rays (1/dir
// infinite), rays exactly through shared edges and vertices, shadow and bounce
// rays leaving big walls, the bunny and scenes with spheres, for several leaf
// sizes and bin counts; any hit agrees with closest hit; degenerate inputs
// (no primitive, one, a thousand identical ones); a well-formed structure.
// (tests/numerics and tests/every_scene_every_technique_test.cpp run their
// cases on every registered accelerator, bvh4 included.)
#include "accel/wide_bvh.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_support.h"

#include "modules/registry.h"
#include "render/ray_offset.h"
#include "scene/camera.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

using testing_support::makeRay;

std::unique_ptr<Accelerator> build(const std::string& name, const Geometry& g,
                                   const std::vector<std::string>& sets = {}) {
  const AcceleratorInfo& info = findAccelerator(name);
  ParamSet params("accelerator '" + name + "'", info.params);
  for (const std::string& s : sets) params.assign(s);
  return buildAccelerator(info, params, g);
}

// One ray: bvh4 finds what brute force finds, to the bit; occluded agrees. Adds 1 to `hits` on a hit.
void expectSameHit(const Accelerator& none, const Accelerator& wide, const Ray& r, size_t i, int& hits) {
  QueryCounters counters;
  Hit expected, hit;
  const bool expectedFound = none.intersect(r, expected, counters);
  const bool found = wide.intersect(r, hit, counters);
  hits += found;
  ASSERT_EQ(found, expectedFound) << "ray " << i << " (" << r.origin.x << ", " << r.origin.y << ", " << r.origin.z
                                  << ") dir (" << r.dir.x << ", " << r.dir.y << ", " << r.dir.z << ")";
  ASSERT_EQ(wide.occluded(r, counters), expectedFound) << "ray " << i;
  if (!found) return;
  ASSERT_EQ(hit.prim, expected.prim) << "ray " << i << " t " << hit.t << " vs " << expected.t;
  ASSERT_EQ(std::bit_cast<uint32_t>(hit.t), std::bit_cast<uint32_t>(expected.t)) << "ray " << i;
  ASSERT_EQ(std::bit_cast<uint32_t>(hit.b1), std::bit_cast<uint32_t>(expected.b1)) << "ray " << i;
  ASSERT_EQ(std::bit_cast<uint32_t>(hit.b2), std::bit_cast<uint32_t>(expected.b2)) << "ray " << i;
}

// Every ray of `rays` through expectSameHit, bvh4 built with `sets`; stops at the first failure.
// Returns how many rays hit.
int expectSameAsBruteForce(const Geometry& g, const std::vector<Ray>& rays,
                           const std::vector<std::string>& sets = {}) {
  const auto none = build("none", g);
  const auto wide = build("bvh4", g, sets);
  int hits = 0;
  for (size_t i = 0; i < rays.size() && !testing::Test::HasFatalFailure(); ++i)
    expectSameHit(*none, *wide, rays[i], i, hits);
  return hits;
}

uint32_t addTriangle(Geometry& g, Vec3 a, Vec3 b, Vec3 c) {
  const auto base = static_cast<uint32_t>(g.positions.size());
  g.positions.insert(g.positions.end(), {a, b, c});
  g.triangles.emplace_back(base, base + 1, base + 2);
  g.triangleObject.push_back(0);
  return g.triangleCount() - 1;
}

void addSphere(Geometry& g, Vec3 c, float r) {
  g.spheres.push_back({c, r});
  g.sphereObject.push_back(1);
}

// n random triangles (edges up to `size`) in the cube [-1, 1]^3.
Geometry randomSoup(int n, float size, unsigned seed) {
  Geometry g;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < n; ++i) {
    const Vec3 c(u(rng), u(rng), u(rng));
    addTriangle(g, c + size * Vec3(u(rng), u(rng), u(rng)), c + size * Vec3(u(rng), u(rng), u(rng)),
                c + size * Vec3(u(rng), u(rng), u(rng)));
  }
  return g;
}

// Random origins in [-extent, extent]^3, random directions of random length, some with a tmin/tmax window.
std::vector<Ray> randomRays(int n, float extent, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), len(0.1f, 10.0f), window(0.0f, 2.0f);
  std::normal_distribution<float> normal;
  std::vector<Ray> rays;
  for (int i = 0; i < n; ++i) {
    const Vec3 o = extent * Vec3(u(rng), u(rng), u(rng));
    const Vec3 d = len(rng) * glm::normalize(Vec3(normal(rng), normal(rng), normal(rng)));
    if (i % 4 == 3) {
      const float tmin = window(rng);
      rays.push_back(makeRay(o, d, tmin, tmin + window(rng)));
    } else {
      rays.push_back(makeRay(o, d));
    }
  }
  return rays;
}

// Rays along +-x, +-y, +-z (the other components +0 or -0), from origins on a grid that includes the
// triangles' own coordinates, so origins lie exactly in box faces (0 * inf in the slab test).
std::vector<Ray> axisRays(const Geometry& g, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<size_t> pick(0, g.positions.size() - 1);
  std::uniform_real_distribution<float> u(-1.2f, 1.2f);
  std::vector<Ray> rays;
  for (int i = 0; i < 1500; ++i) {
    Vec3 o = i % 2 == 0 ? g.positions[pick(rng)] : Vec3(u(rng), u(rng), u(rng));
    if (i % 3 == 0) o = Vec3(g.positions[pick(rng)].x, g.positions[pick(rng)].y, u(rng));  // on two box planes
    for (int axis = 0; axis < 3; ++axis)
      for (float sign : {1.0f, -1.0f})
        for (float zero : {0.0f, -0.0f}) {
          Vec3 d(zero);
          d[axis] = sign;
          Vec3 start = o;
          start[axis] = -3.0f * sign;  // from outside the scene
          rays.push_back(makeRay(start, d));
          rays.push_back(makeRay(o, d));  // from inside, on the planes
        }
  }
  return rays;
}

TEST(WideBvh, RandomRaysHitWhatBruteForceHits) {
  Geometry g = randomSoup(3000, 0.08f, 7);
  for (int i = 0; i < 40; ++i)
    addSphere(g, Vec3(-0.9f + 0.045f * float(i), 0.1f * float(i % 7) - 0.3f, 0.0f), 0.03f);
  const std::vector<Ray> rays = randomRays(20000, 1.5f, 11);
  EXPECT_GT(expectSameAsBruteForce(g, rays), 2000);
  // Other leaf sizes and bin counts: other trees, the same answers.
  for (const std::vector<std::string>& sets : std::vector<std::vector<std::string>>{
           {"max_leaf=1", "bins=2"}, {"max_leaf=16", "bins=64"}, {"max_leaf=7", "bins=5"}}) {
    SCOPED_TRACE(sets[0] + " " + sets[1]);
    expectSameAsBruteForce(g, std::vector<Ray>(rays.begin(), rays.begin() + 4000), sets);
  }
}

TEST(WideBvh, AxisParallelRaysThroughBoxFaces) {
  // Axis-aligned triangles (flat boxes) on a grid of coordinates, plus tilted ones.
  Geometry g;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j) {
      const float x = 0.25f * float(i), y = 0.25f * float(j);
      addTriangle(g, {x, y, 0.5f}, {x + 0.25f, y, 0.5f}, {x, y + 0.25f, 0.5f});          // in z = 0.5
      addTriangle(g, {x, -0.5f, y}, {x + 0.25f, -0.5f, y}, {x, -0.5f, y + 0.25f});        // in y = -0.5
      addTriangle(g, {0.75f, x, y}, {0.75f, x + 0.25f, y}, {0.75f, x, y + 0.25f});        // in x = 0.75
      addTriangle(g, {x, y, -0.25f}, {x + 0.25f, y + 0.25f, 0.0f}, {x, y + 0.25f, 0.1f});  // tilted
    }
  addSphere(g, Vec3(0.0f), 0.3f);
  EXPECT_GT(expectSameAsBruteForce(g, axisRays(g, 3)), 1000);
  expectSameAsBruteForce(g, axisRays(g, 4), {"max_leaf=1"});
}

TEST(WideBvh, RaysThroughSharedEdgesAndVerticesOfAMesh) {
  // A bumpy height field of 2 x 40 x 40 triangles sharing edges and vertices by index.
  Geometry g;
  const int n = 40;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float x = -1.0f + 2.0f * float(i) / float(n), z = -1.0f + 2.0f * float(j) / float(n);
      g.positions.emplace_back(x, 0.1f * std::sin(7.0f * x) * std::cos(5.0f * z), z);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto v = static_cast<unsigned>(j * (n + 1) + i);
      const unsigned w = static_cast<unsigned>(n + 1);
      g.triangles.emplace_back(v, v + 1, v + w + 1);
      g.triangles.emplace_back(v, v + w + 1, v + w);
      g.triangleObject.insert(g.triangleObject.end(), {0u, 0u});
    }
  // Rays from above and below aimed exactly at vertices and at points on edges away from the border.
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f), s(0.0f, 1.0f);
  std::uniform_int_distribution<int> cell(1, n - 2);
  std::vector<Ray> rays;
  for (int k = 0; k < 6000; ++k) {
    const glm::uvec3& t = g.triangles[static_cast<size_t>(2 * (cell(rng) * n + cell(rng)) + k % 2)];
    const Vec3 a = g.positions[t.x], b = g.positions[t.y];
    const Vec3 target = k % 3 == 0 ? a : a + s(rng) * (b - a);
    const Vec3 o(u(rng), k % 2 == 0 ? 2.0f : -2.0f, u(rng));
    rays.push_back(makeRay(o, target - o));
    rays.push_back(makeRay(Vec3(target.x, 3.0f, target.z), Vec3(0.0f, -1.0f, 0.0f)));  // straight down
  }
  EXPECT_EQ(expectSameAsBruteForce(g, rays), static_cast<int>(rays.size()));  // no crack: every ray hits
}

// Shadow and bounce rays leaving big flat walls (coordinates in the hundreds, as in the Cornell box) from
// offset hit points: the triangle test's t there is off by more than the offset, so brute force may
// even report the wall itself just behind the origin -- the boxes must be entered all the same.
TEST(WideBvh, RaysLeavingWallsAsBruteForceSeesThem) {
  Geometry g;
  const float s = 555.0f;
  auto quad = [&g](Vec3 o, Vec3 e1, Vec3 e2) {
    addTriangle(g, o, o + e1, o + e1 + e2);
    addTriangle(g, o, o + e1 + e2, o + e2);
  };
  quad({0, 0, 0}, {s, 0, 0}, {0, 0, s});        // floor
  quad({0, s, 0}, {0, 0, s}, {s, 0, 0});        // ceiling
  quad({0, 0, s}, {s, 0, 0}, {0, s, 0});        // back
  quad({0, 0, 0}, {0, 0, s}, {0, s, 0});        // x = 0
  quad({s, 0, 0}, {0, s, 0}, {0, 0, s});        // x = s
  quad({130, 165, 65}, {-48, 0, 160}, {160, 0, 49});  // a block's top, tilted edges
  addSphere(g, Vec3(400.0f, 100.0f, 300.0f), 90.0f);
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::normal_distribution<float> normal;
  const Vec3 light(278.0f, 545.0f, 279.5f);
  std::vector<Ray> rays;
  for (int i = 0; i < 20000; ++i) {
    const glm::uvec3& t = g.triangles[static_cast<size_t>(i) % g.triangles.size()];
    const Vec3 p0 = g.positions[t.x], p1 = g.positions[t.y], p2 = g.positions[t.z];
    float a = u(rng), b = u(rng);
    if (a + b > 1.0f) {
      a = 1.0f - a;
      b = 1.0f - b;
    }
    const Vec3 p = p0 + a * (p1 - p0) + b * (p2 - p0);
    Vec3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    if (glm::dot(n, light - p) < 0.0f) n = -n;
    const Vec3 origin = offsetRayOrigin(p, n);
    rays.push_back(makeRay(origin, light - origin, 0.0f, 1.0f - 1e-4f));  // shadow ray
    const Vec3 d = glm::normalize(n + glm::normalize(Vec3(normal(rng), normal(rng), normal(rng))));
    rays.push_back(makeRay(origin, d));  // bounce
  }
  EXPECT_GT(expectSameAsBruteForce(g, rays), 10000);
}

TEST(WideBvh, BunnyCameraAndRandomRays) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/bunny.json");
  Camera cam = scene.camera;
  cam.width = cam.height = 96;
  const CameraFrame frame(cam);
  std::vector<Ray> rays;
  for (int y = 0; y < cam.height; ++y)
    for (int x = 0; x < cam.width; ++x)
      rays.push_back(referenceCameraRay(cam, frame, float(x) + 0.5f, float(y) + 0.5f));
  const Bounds3 b = scene.geometry.sceneBounds();
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::normal_distribution<float> normal;
  for (int i = 0; i < 10000; ++i)
    rays.push_back(makeRay(b.min + Vec3(u(rng), u(rng), u(rng)) * b.extent(),
                           glm::normalize(Vec3(normal(rng), normal(rng), normal(rng)))));
  EXPECT_GT(expectSameAsBruteForce(scene.geometry, rays), 3000);

  // A complexity probe: a small fraction of the bunny's triangles per ray.
  const auto wide = build("bvh4", scene.geometry);
  QueryCounters counters;
  for (const Ray& r : rays) {
    Hit h;
    wide->intersect(r, h, counters);
  }
  const double perRay = double(counters.primitivesTested) / double(rays.size());
  EXPECT_GT(counters.nodesVisited, rays.size());
  EXPECT_LT(perRay, 0.02 * double(scene.geometry.primitiveCount()));
}

TEST(WideBvh, ScenesWithSpheres) {
  for (const char* name : {"metal_spheres.json", "whitted_1980.json", "glass_and_water.json"}) {
    SCOPED_TRACE(name);
    const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/" + name);
    ASSERT_FALSE(scene.geometry.spheres.empty());
    const Bounds3 b = scene.geometry.sceneBounds();
    const float extent = 0.6f * std::max({b.extent().x, b.extent().y, b.extent().z});
    std::vector<Ray> rays = randomRays(6000, extent, 23);
    for (Ray& r : rays) r.origin += b.center();
    EXPECT_GT(expectSameAsBruteForce(scene.geometry, rays), 500);
  }
  // Nested and touching spheres among triangles: hits from inside return the exit.
  Geometry g = randomSoup(200, 0.2f, 9);
  addSphere(g, Vec3(0.0f), 0.5f);
  addSphere(g, Vec3(0.0f), 0.25f);
  addSphere(g, Vec3(1.0f, 0.0f, 0.0f), 0.5f);
  std::vector<Ray> rays = randomRays(5000, 0.4f, 29);
  EXPECT_GT(expectSameAsBruteForce(g, rays), 3000);
}

TEST(WideBvh, EmptySceneHitsNothing) {
  const Geometry g;
  const auto wide = build("bvh4", g);
  QueryCounters counters;
  Hit hit;
  EXPECT_FALSE(wide->intersect(makeRay(Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f)), hit, counters));
  EXPECT_FALSE(hit.valid());
  EXPECT_FALSE(wide->occluded(makeRay(Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f)), counters));
  EXPECT_EQ(wide->stats().nodeCount, 0u);
  EXPECT_TRUE(wide->nodesAtDepth(0).empty());
}

TEST(WideBvh, SingleTriangle) {
  Geometry g;
  addTriangle(g, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const auto wide = build("bvh4", g);
  QueryCounters counters;
  Hit hit;
  ASSERT_TRUE(wide->intersect(makeRay({0.25f, 0.5f, 5.0f}, {0, 0, -1}), hit, counters));
  EXPECT_EQ(hit.prim, 0u);
  EXPECT_FLOAT_EQ(hit.t, 5.0f);
  EXPECT_FLOAT_EQ(hit.b1, 0.25f);
  EXPECT_FLOAT_EQ(hit.b2, 0.5f);
  EXPECT_FALSE(wide->intersect(makeRay({0.25f, 0.5f, 5.0f}, {0, 0, -1}, 0.0f, 4.9f), hit, counters));
  EXPECT_FALSE(wide->occluded(makeRay({0.75f, 0.5f, 5.0f}, {0, 0, -1}), counters));
  EXPECT_EQ(wide->stats().nodeCount, 1u);
  EXPECT_EQ(wide->stats().depth, 1);
  expectSameAsBruteForce(g, randomRays(2000, 1.0f, 31));
  expectSameAsBruteForce(g, axisRays(g, 32));
}

TEST(WideBvh, ManyIdenticalTrianglesGiveTheSmallestIdOnTies) {
  // 1000 copies of one triangle (and a sphere): no plane separates them, so the build halves them; every
  // copy is hit at the same t and brute force keeps the first.
  Geometry g;
  for (int i = 0; i < 1000; ++i) addTriangle(g, {-1, -1, 0}, {1, -1, 0}, {0, 1, 0});
  addSphere(g, Vec3(0.0f, 0.0f, 3.0f), 0.1f);
  const std::vector<std::vector<std::string>> settings = {{}, {"max_leaf=1"}, {"max_leaf=16"}};
  for (const std::vector<std::string>& sets : settings) {
    const auto wide = build("bvh4", g, sets);
    QueryCounters counters;
    Hit hit;
    ASSERT_TRUE(wide->intersect(makeRay({0.1f, -0.2f, 5.0f}, {0, 0, -1}), hit, counters));
    EXPECT_EQ(hit.prim, 0u);
    EXPECT_FLOAT_EQ(hit.t, 5.0f);
    EXPECT_LE(wide->stats().depth, kWideBvhMaxDepth);
    expectSameAsBruteForce(g, randomRays(2000, 1.0f, 37), sets);
  }
}

TEST(WideBvh, TrianglesWithCollinearVerticesAreNeverHit) {
  // Slivers (three points on a line, two equal, all equal) among proper triangles, in the packets' lanes
  // beside them: those whose float cross product is 0 are stored as all 0 (the four-lane test's
  // precondition) and never hit, as brute force says; a rounded midpoint may leave a true sliver, hit as by
  // brute force.
  Geometry g = randomSoup(200, 0.3f, 41);
  std::mt19937 rng(43);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < 200; ++i) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    const Vec3 c = i % 3 == 0 ? a + 0.5f * (b - a) : i % 3 == 1 ? b : a;
    addTriangle(g, a, i % 3 == 2 ? a : b, c);
  }
  std::vector<Ray> rays = randomRays(3000, 1.0f, 47);
  for (int i = 200; i < 400; i += 2) {  // aimed at the slivers' points, along and across their lines
    const Vec3 p = g.positions[g.triangles[static_cast<size_t>(i)][0]];
    rays.push_back(makeRay(p + Vec3(0.0f, 0.0f, 2.0f), Vec3(0.0f, 0.0f, -1.0f)));
    rays.push_back(makeRay(p - (g.positions[g.triangles[static_cast<size_t>(i)][1]] - p), g.positions[g.triangles[static_cast<size_t>(i)][1]] - p));
  }
  for (const std::vector<std::string>& sets : {std::vector<std::string>{}, {"max_leaf=16"}}) {
    expectSameAsBruteForce(g, rays, sets);
    const auto wide = build("bvh4", g, sets);
    QueryCounters counters;
    for (const Ray& r : rays) {
      Hit hit;
      if (wide->intersect(r, hit, counters)) {
        const auto& tri = g.triangles[hit.prim];
        EXPECT_NE(glm::cross(g.positions[tri[1]] - g.positions[tri[0]], g.positions[tri[2]] - g.positions[tri[0]]),
                  Vec3(0.0f))
            << "primitive " << hit.prim;
      }
    }
  }
}

bool contains(const Bounds3& outer, const Bounds3& inner) {
  return glm::all(glm::lessThanEqual(outer.min, inner.min)) && glm::all(glm::lessThanEqual(inner.max, outer.max));
}

// Every primitive in exactly one leaf, leaves no bigger than max_leaf, every box holding its children's
// and its primitives', nodes in depth-first order, and the GUI's overlay boxes.
TEST(WideBvh, WellFormedStructure) {
  Geometry g = randomSoup(5000, 0.05f, 41);  // > 4096 primitives: the parallel build
  for (int i = 0; i < 30; ++i) addSphere(g, Vec3(0.06f * float(i) - 0.9f, 0.0f, 0.5f), 0.02f);
  for (int maxLeaf : {1, 4, 9}) {
    SCOPED_TRACE(maxLeaf);
    WideBvhSettings settings;
    settings.maxLeaf = maxLeaf;
    const WideBvh bvh = buildWideBvh(g, settings);
    ASSERT_FALSE(bvh.nodes.empty());
    std::vector<int> seen(g.primitiveCount(), 0);
    int leaves = 0;
    std::vector<uint32_t> stack{0u};
    while (!stack.empty()) {
      const uint32_t index = stack.back();
      stack.pop_back();
      const WideBvhNode& node = bvh.nodes[index];
      for (int i = 0; i < 4; ++i) {
        if (!node.used(i)) {
          EXPECT_EQ(node.count[i], 0u);
          continue;
        }
        if (!node.isLeaf(i)) {
          EXPECT_GT(node.child[i], index);  // depth-first order: children after their parent
          const Bounds3 outer = node.childBounds(i), inner = bvh.nodes[node.child[i]].childBounds(0);
          EXPECT_TRUE(contains(outer, inner));
          stack.push_back(node.child[i]);
        }
      }
      for (int i = 0; i < 4; ++i) {
        if (!node.used(i) || !node.isLeaf(i)) continue;
        ++leaves;
        EXPECT_LE(node.count[i], static_cast<uint32_t>(maxLeaf));
        const Bounds3 box = node.childBounds(i);
        for (uint32_t s = 0; s < (node.count[i] + 3) / 4 * 4; ++s) {
          const WideBvhPacket& packet = bvh.packets[node.child[i] + s / 4];
          const uint32_t prim = packet.prim[s % 4];
          if (s >= node.count[i]) {  // the last packet's unused lanes
            EXPECT_EQ(prim, WideBvhPacket::kEmpty);
            continue;
          }
          ++seen[prim];
          const Bounds3 pb = g.bounds(prim);
          EXPECT_TRUE(contains(box, pb));
          const bool stored = g.isTriangle(prim) && glm::cross(g.positions[g.triangles[prim][1]] - g.positions[g.triangles[prim][0]],
                                                               g.positions[g.triangles[prim][2]] - g.positions[g.triangles[prim][0]]) != Vec3(0.0f);
          for (int k = 0; k < 3; ++k)
            EXPECT_EQ(packet.vertex(k, int(s % 4)), stored ? g.positions[g.triangles[prim][k]] : Vec3(0.0f));
        }
      }
    }
    for (uint32_t p = 0; p < g.primitiveCount(); ++p) ASSERT_EQ(seen[p], 1) << "primitive " << p;
    EXPECT_GE(leaves, static_cast<int>(g.primitiveCount()) / maxLeaf);
    EXPECT_GT(bvh.sahCost, 0.0);
    EXPECT_GT(bvh.depth, 1);
  }
  // The overlay: the root box is the scene's, and every level's boxes lie in it.
  const auto wide = build("bvh4", g);
  const AcceleratorStats st = wide->stats();
  EXPECT_GT(st.nodeCount, g.primitiveCount() / 16);
  EXPECT_GT(st.memoryBytes, st.nodeCount * sizeof(WideBvhNode));
  EXPECT_GE(st.buildSeconds, 0.0);
  const std::vector<NodeShape> root = wide->nodesAtDepth(0);
  ASSERT_EQ(root.size(), 1u);
  EXPECT_EQ(root[0].box.min, g.sceneBounds().min);
  EXPECT_EQ(root[0].box.max, g.sceneBounds().max);
  EXPECT_FALSE(root[0].leaf);
  const std::vector<NodeShape> deep = wide->nodesAtDepth(st.depth);
  EXPECT_GT(deep.size(), 100u);
  for (const NodeShape& s : deep) EXPECT_TRUE(s.leaf);  // at the deepest level: leaves only
}

TEST(WideBvh, TheParallelBuildIsDeterministic) {
  const Geometry g = randomSoup(20000, 0.03f, 43);
  const WideBvh a = buildWideBvh(g, {}), b = buildWideBvh(g, {});
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (size_t i = 0; i < a.nodes.size(); ++i)
    ASSERT_EQ(std::memcmp(&a.nodes[i], &b.nodes[i], sizeof(WideBvhNode)), 0) << "node " << i;
  ASSERT_EQ(a.packets.size(), b.packets.size());
  for (size_t i = 0; i < a.packets.size(); ++i)
    ASSERT_EQ(std::memcmp(&a.packets[i], &b.packets[i], sizeof(WideBvhPacket)), 0) << "packet " << i;
}

}  // namespace
}  // namespace ll
