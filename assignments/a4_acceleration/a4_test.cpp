// Assignment 4 (acceleration structures): every registered accelerator, in
// every configuration, against brute force on the bunny, the Cornell box with
// the bunny and a hand-made geometry of hard cases; the BVH's structure and
// statistics, the KD-tree's and the octree's; a complexity probe for all
// three; and the four student tasks.
//
// Exactness: `bvh`, `kdtree` and `octree` must return brute force's closest hit bit for bit (t,
// primitive, barycentrics) and the same occlusion answer. `embree` uses its
// own triangle test, so t may differ by rounding and a ray exactly through a
// shared edge or vertex may report the neighbour; hit/miss may differ only on
// such grazing rays (a tiny fraction).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "test_support.h"

#include "a4_tasks.h"
#include "bsp_cell.h"
#include "bvh.h"
#include "kdtree.h"
#include "octree.h"
#include "modules/registry.h"
#include "render/student_task.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

using testing_support::makeRay;

// Success if calling `probe` did not run the stub of task `id`.
template <class F>
testing::AssertionResult implemented(const char* id, F&& probe) {
  TaskLog log;
  {
    const ScopedTaskLog scope(&log);
    probe();
  }
  const auto missing = log.missing();
  const auto it = missing.find(id);
  if (it == missing.end()) return testing::AssertionSuccess();
  return testing::AssertionFailure() << id << " not implemented (" << it->second << ")";
}

// --- Configurations: every accelerator in the registry, every BVH variant ----------

struct Config {
  std::string accelerator;
  std::vector<std::string> sets;  // name=value
  std::string label() const {
    std::string s = accelerator;
    for (const auto& a : sets) s += " " + a;
    return s;
  }
  bool exact() const { return accelerator != "embree"; }
};

std::vector<Config> allConfigs() {
  std::vector<Config> configs;
  for (const AcceleratorInfo& info : accelerators()) {
    if (info.name == "none") continue;
    if (info.name == "bvh") {
      for (const char* split : {"median", "equal-counts", "sah"})
        for (const char* volume : {"box", "sphere"})
          configs.push_back({"bvh", {std::string("split=") + split, std::string("volume=") + volume}});
      configs.push_back({"bvh", {"split=sah", "max_leaf=1", "bins=2"}});
      configs.push_back({"bvh", {"split=median", "max_leaf=64"}});
    } else if (info.name == "kdtree") {
      configs.push_back({"kdtree", {}});
      configs.push_back({"kdtree", {"max_leaf=1", "intersection_cost=4", "empty_bonus=0.9"}});
      configs.push_back({"kdtree", {"max_depth=3", "max_leaf=64", "traversal_cost=10"}});
      configs.push_back({"kdtree", {"build=binned"}});
      configs.push_back({"kdtree", {"build=binned", "max_leaf=1", "intersection_cost=4", "empty_bonus=0.9", "bins=2"}});
    } else if (info.name == "bsp") {
      configs.push_back({"bsp", {}});
      configs.push_back({"bsp", {"triangle_planes=16", "axis_planes=4", "max_leaf=1", "intersection_cost=4"}});
      configs.push_back({"bsp", {"triangle_planes=0", "max_depth=3", "max_leaf=64"}});
    } else if (info.name == "octree") {
      configs.push_back({"octree", {}});
      configs.push_back({"octree", {"max_depth=6", "max_leaf=1"}});
      configs.push_back({"octree", {"max_depth=1"}});
    } else {
      configs.push_back({info.name, {}});
    }
  }
  return configs;
}

std::unique_ptr<Accelerator> make(const Config& c, const Geometry& g) {
  const AcceleratorInfo& info = findAccelerator(c.accelerator);
  ParamSet params("accelerator '" + c.accelerator + "'", info.params);
  for (const auto& a : c.sets) params.assign(a);
  return buildAccelerator(info, params, g);
}

// --- Rays: random, aimed, through vertices and edges, axis-parallel, from inside ---

Vec3 randomDirection(std::mt19937& rng) {
  std::normal_distribution<float> n;
  Vec3 d;
  do d = Vec3(n(rng), n(rng), n(rng));
  while (glm::dot(d, d) < 1e-6f);
  return glm::normalize(d);
}

std::vector<Ray> makeRays(const Geometry& g, size_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  const Bounds3 b = g.sceneBounds();
  const Vec3 lo = b.min - 0.25f * b.extent(), span = 1.5f * b.extent();
  auto inBox = [&] { return lo + Vec3(u01(rng), u01(rng), u01(rng)) * span; };
  auto anyPrim = [&] { return static_cast<uint32_t>(rng() % g.primitiveCount()); };
  auto pointOn = [&](uint32_t p) -> Vec3 {
    if (!g.isTriangle(p)) {
      const Sphere& s = g.spheres[p - g.triangleCount()];
      return s.center + s.radius * randomDirection(rng);
    }
    const glm::uvec3& t = g.triangles[p];
    float a = u01(rng), c = u01(rng);
    if (a + c > 1.0f) a = 1.0f - a, c = 1.0f - c;
    return (1.0f - a - c) * g.positions[t.x] + a * g.positions[t.y] + c * g.positions[t.z];
  };
  auto vertex = [&] { return g.positions[rng() % g.positions.size()]; };
  auto edgeMid = [&] {
    const glm::uvec3& t = g.triangles[rng() % g.triangles.size()];
    return 0.5f * (g.positions[t.x] + g.positions[t.y]);
  };
  const bool tris = !g.triangles.empty();
  std::vector<Ray> rays;
  rays.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    const Vec3 o = inBox();
    switch (i % 8) {
      case 0:  // incoherent
        rays.push_back(makeRay(o, randomDirection(rng)));
        break;
      case 1:  // aimed at a point on a primitive (non-unit direction)
        rays.push_back(makeRay(o, pointOn(anyPrim()) - o));
        break;
      case 2:  // through a shared vertex
        rays.push_back(makeRay(o, (tris ? vertex() : pointOn(anyPrim())) - o));
        break;
      case 3:  // through a shared edge
        rays.push_back(makeRay(o, (tris ? edgeMid() : pointOn(anyPrim())) - o));
        break;
      case 4: {  // axis-parallel (two zero components), often exactly along vertex coordinates
        Vec3 d(0.0f);
        const auto axis = static_cast<int>(rng() % 3);
        d[axis] = (rng() & 1) ? 1.0f : -1.0f;
        Vec3 origin = o;
        if (tris && (rng() & 1)) {
          const Vec3 v = vertex();
          origin = v;
          origin[axis] = o[axis];
        }
        rays.push_back(makeRay(origin, d));
        break;
      }
      case 5: {  // one zero component
        Vec3 d = randomDirection(rng);
        d[static_cast<int>(rng() % 3)] = 0.0f;
        if (glm::dot(d, d) == 0.0f) d = Vec3(1.0f, 0.0f, 0.0f);
        rays.push_back(makeRay(o, d));
        break;
      }
      case 6: {  // a segment between two surface points, as a shadow ray (finite tmax)
        const Vec3 a = pointOn(anyPrim()), c = pointOn(anyPrim());
        if (a == c) {
          rays.push_back(makeRay(o, randomDirection(rng)));
          break;
        }
        rays.push_back(makeRay(a, c - a, 1e-4f, 1.0f - 1e-4f));
        break;
      }
      default: {  // from inside the scene, with tmin = 0 and a random finite tmax
        const Vec3 inside = b.min + Vec3(u01(rng), u01(rng), u01(rng)) * b.extent();
        rays.push_back(makeRay(inside, randomDirection(rng), 0.0f, (rng() & 1) ? kInfinity : u01(rng) * b.diagonal()));
        break;
      }
    }
  }
  return rays;
}

// --- The comparison -----------------------------------------------------------------

struct Reference {
  std::vector<Hit> hits;
  std::vector<char> occluded;
};

// Brute force's answers. Its occlusion answer equals "the closest hit exists"
// (both test every primitive on (tmin, tmax)); checked on the first rays,
// then taken from the closest hit to halve the test's time.
Reference bruteForce(const Geometry& g, const std::vector<Ray>& rays) {
  const auto none = make({"none", {}}, g);
  Reference ref;
  ref.hits.resize(rays.size());
  ref.occluded.resize(rays.size());
  QueryCounters counters;
  for (size_t i = 0; i < rays.size(); ++i) {
    none->intersect(rays[i], ref.hits[i], counters);
    ref.occluded[i] = ref.hits[i].valid();
    if (i < 2000) {
      EXPECT_EQ(none->occluded(rays[i], counters), ref.hits[i].valid()) << "ray " << i;
    }
  }
  return ref;
}

// makeRays' kinds 2-5 aim exactly at vertices and edges or run along axes:
// there Embree's triangle test may differ from ours by rounding.
bool grazing(size_t i, size_t generated) { return i >= generated || (i % 8 >= 2 && i % 8 <= 5); }

// Whether embree's answer `h` is as good as brute force's `r`: the same hit
// point to 1e-5 of the scene's size (Embree computes t its own way), and the
// primitive either the same or one hit at that point too (a tie, or a ray
// through a shared edge).
bool closeEnough(const Geometry& g, const Ray& ray, const Hit& h, const Hit& r) {
  if (h.valid() != r.valid()) return false;
  if (!h.valid()) return true;
  const float tol = 1e-5f * g.sceneBounds().diagonal() / glm::length(ray.dir) + 1e-5f * std::abs(r.t);
  if (std::abs(h.t - r.t) > tol) return false;
  if (h.prim == r.prim) return true;
  Hit alone;
  alone.t = kInfinity;
  const bool hits = g.intersect(h.prim, ray, WatertightRay(ray), alone);
  return !hits || std::abs(alone.t - r.t) <= tol;  // a miss by our test: it grazed the shared edge
}

// `generated`: how many of `rays` came from makeRays (the rest are hand-made grazing rays).
void expectMatchesBruteForce(const Geometry& g, const std::vector<Ray>& rays, size_t generated, const Reference& ref,
                             const std::vector<Config>& configs) {
  for (const Config& c : configs) {
    SCOPED_TRACE(c.label());
    const auto accel = make(c, g);
    QueryCounters counters;
    size_t wrongHits = 0, wrongOcclusion = 0, wrongGrazing = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
      Hit h;
      const bool found = accel->intersect(rays[i], h, counters);
      const Hit& r = ref.hits[i];
      const bool same = c.exact() ? (found == r.valid() && h.prim == r.prim && h.t == r.t && h.b1 == r.b1 &&
                                     h.b2 == r.b2)
                                  : (found == h.valid() && closeEnough(g, rays[i], h, r));
      const bool occ = accel->occluded(rays[i], counters);
      const bool occSame = occ == (ref.occluded[i] != 0);
      if (!c.exact()) {
        // Embree skips zero-area triangles (the loaders drop them too) and may
        // decide rays through vertices and edges, or grazing a surface, the
        // other way: counted, and only their number is checked.
        const bool degenerate = r.valid() && g.area(r.prim) == 0.0f;
        if (grazing(i, generated) || degenerate)
          wrongGrazing += (!same || !occSame) ? 1 : 0;
        else {
          wrongHits += same ? 0 : 1;
          wrongOcclusion += occSame ? 0 : 1;
        }
        continue;
      }
      if (!same && ++wrongHits <= 3)
        ADD_FAILURE() << "ray " << i << " o=(" << rays[i].origin.x << "," << rays[i].origin.y << ","
                      << rays[i].origin.z << ") d=(" << rays[i].dir.x << "," << rays[i].dir.y << "," << rays[i].dir.z
                      << ") [" << rays[i].tmin << "," << rays[i].tmax << "]: got " << testing_support::describeHit(h)
                      << ", brute force " << testing_support::describeHit(r);
      if (!occSame && ++wrongOcclusion <= 3)
        ADD_FAILURE() << "ray " << i << ": occluded() says " << (occ ? "blocked" : "free") << ", brute force "
                      << (ref.occluded[i] != 0 ? "blocked" : "free");
    }
    // Embree's own triangle test may decide a few rays grazing an edge differently.
    const size_t allowed = c.exact() ? 0 : rays.size() / 5000;
    EXPECT_LE(wrongHits, allowed) << "closest hits differing from brute force, of " << rays.size();
    EXPECT_LE(wrongOcclusion, allowed) << "occlusion answers differing from brute force, of " << rays.size();
    EXPECT_LE(wrongGrazing, rays.size() / 50) << "answers differing on rays through vertices and edges";
    if (!c.exact())
      std::printf("[ %s ] answers differing: %zu closest, %zu occlusion of %zu ordinary rays; %zu of the rays through "
                  "vertices, edges, degenerate triangles\n",
                  c.label().c_str(), wrongHits, wrongOcclusion, rays.size(), wrongGrazing);
  }
}

// Whether `accelerator` runs without the stub of task `id`.
bool taskImplemented(const Geometry& g, const std::string& accelerator, const char* id) {
  const auto accel = make({accelerator, {}}, g);
  QueryCounters c;
  Hit h;
  const Ray probe = makeRay(g.sceneBounds().center() - Vec3(0, 0, 100), {0, 0, 1});
  return implemented(id, [&] { accel->intersect(probe, h, c); });
}

// Whether the BVH runs without stubs (A4.1 and A4.2 written).
bool bvhImplemented(const Geometry& g) { return taskImplemented(g, "bvh", "A4.1") && taskImplemented(g, "bvh", "A4.2"); }

// Whether every A4 task is written (else the scene tests use fewer rays: stubs are brute force).
bool allImplemented(const Geometry& g) {
  return bvhImplemented(g) && taskImplemented(g, "kdtree", "A4.3") && taskImplemented(g, "octree", "A4.4") &&
         taskImplemented(g, "bsp", "A4.5");
}

// Checks quarter `part` (0-3) of the scene's 100k rays: four test cases per
// scene, so that a parallel ctest spreads the brute-force work and each case
// stays well under 10 s.
void checkScene(const std::string& file, int part) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/" + file);
  // With a stub an accelerator is brute force: still checked, on fewer rays to stay quick.
  const size_t total = allImplemented(scene.geometry) ? 100000 : 4000;  // quarters: multiples of 8 (see grazing())
  const std::vector<Ray> all = makeRays(scene.geometry, total, 4242);
  const auto begin = all.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(part) * total / 4);
  const std::vector<Ray> rays(begin, begin + static_cast<std::ptrdiff_t>(total / 4));
  const Reference ref = bruteForce(scene.geometry, rays);
  expectMatchesBruteForce(scene.geometry, rays, rays.size(), ref, allConfigs());
}

TEST(A4_Accelerators, MatchBruteForceOnTheBunnyQuarter1) { checkScene("bunny.json", 0); }
TEST(A4_Accelerators, MatchBruteForceOnTheBunnyQuarter2) { checkScene("bunny.json", 1); }
TEST(A4_Accelerators, MatchBruteForceOnTheBunnyQuarter3) { checkScene("bunny.json", 2); }
TEST(A4_Accelerators, MatchBruteForceOnTheBunnyQuarter4) { checkScene("bunny.json", 3); }
TEST(A4_Accelerators, MatchBruteForceOnTheCornellBunnyQuarter1) { checkScene("cornell_bunny.json", 0); }
TEST(A4_Accelerators, MatchBruteForceOnTheCornellBunnyQuarter2) { checkScene("cornell_bunny.json", 1); }
TEST(A4_Accelerators, MatchBruteForceOnTheCornellBunnyQuarter3) { checkScene("cornell_bunny.json", 2); }
TEST(A4_Accelerators, MatchBruteForceOnTheCornellBunnyQuarter4) { checkScene("cornell_bunny.json", 3); }

// --- Hard cases, made by hand -----------------------------------------------------

void addTriangle(Geometry& g, Vec3 a, Vec3 b, Vec3 c) {
  const auto base = static_cast<uint32_t>(g.positions.size());
  g.positions.insert(g.positions.end(), {a, b, c});
  g.triangles.emplace_back(base, base + 1, base + 2);
  g.triangleObject.push_back(0);
}

void addQuad(Geometry& g, Vec3 o, Vec3 e1, Vec3 e2) {  // two triangles sharing the diagonal
  addTriangle(g, o, o + e1, o + e1 + e2);
  addTriangle(g, o, o + e1 + e2, o + e2);
}

void addSphere(Geometry& g, Vec3 c, float r) {
  g.spheres.push_back({c, r});
  g.sphereObject.push_back(0);
}

Geometry hardCases() {
  Geometry g;
  // Axis-aligned grids in the planes x = 0, 1, 2: median splits fall exactly on x = 1.
  for (int plane = 0; plane < 3; ++plane)
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        addQuad(g, Vec3(float(plane), float(i) / 6.0f, float(j) / 6.0f), Vec3(0, 1.0f / 6.0f, 0),
                Vec3(0, 0, 1.0f / 6.0f));
  // The same triangle ten times (identical centroids, identical t: ties go to the smaller id).
  for (int i = 0; i < 10; ++i) addTriangle(g, {0.2f, 0.2f, 1.5f}, {0.8f, 0.3f, 1.5f}, {0.4f, 0.9f, 1.5f});
  // Different triangles around one centroid.
  for (int i = 0; i < 12; ++i) {
    const float a = float(i) * 0.5f;
    const Vec3 c(1.5f, 0.5f, 0.5f), u(std::cos(a), std::sin(a), 0.3f), v(-std::sin(a), std::cos(a), -0.2f);
    addTriangle(g, c + 0.3f * u, c + 0.3f * v - 0.15f * u, c - 0.3f * v - 0.15f * u);
  }
  // Degenerate triangles: a repeated vertex, collinear vertices, a point.
  addTriangle(g, {0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, {0.9f, 0.1f, 0.3f});
  addTriangle(g, {0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}, {2.0f, 2.0f, 2.0f});
  addTriangle(g, {1.2f, 0.7f, 0.1f}, {1.2f, 0.7f, 0.1f}, {1.2f, 0.7f, 0.1f});
  // A closed unit cube (rays start inside it) sharing the plane x = 2 with a grid.
  const Vec3 c0(2.0f, 0.0f, 0.0f);
  addQuad(g, c0, {1, 0, 0}, {0, 1, 0});
  addQuad(g, c0 + Vec3(0, 0, 1), {0, 1, 0}, {1, 0, 0});
  addQuad(g, c0, {0, 0, 1}, {1, 0, 0});
  addQuad(g, c0 + Vec3(0, 1, 0), {1, 0, 0}, {0, 0, 1});
  addQuad(g, c0, {0, 1, 0}, {0, 0, 1});
  addQuad(g, c0 + Vec3(1, 0, 0), {0, 0, 1}, {0, 1, 0});
  // Spheres: duplicates, nested, tiny, one crossing a grid plane.
  addSphere(g, {0.5f, 1.5f, 0.5f}, 0.3f);
  addSphere(g, {0.5f, 1.5f, 0.5f}, 0.3f);
  addSphere(g, {0.5f, 1.5f, 0.5f}, 0.1f);
  addSphere(g, {1.0f, 0.5f, 0.5f}, 0.2f);
  addSphere(g, {2.5f, 0.5f, 0.5f}, 1e-3f);
  return g;
}

TEST(A4_Accelerators, MatchBruteForceOnHardCases) {
  const Geometry g = hardCases();
  std::vector<Ray> rays = makeRays(g, 100000, 7);
  const size_t generated = rays.size();
  // Axis-parallel rays exactly along the grid lines, edges and vertices of the planes.
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 6; ++j)
      for (float s : {1.0f, -1.0f}) {
        const float y = float(i) / 6.0f, z = float(j) / 6.0f;
        rays.push_back(makeRay({s > 0 ? -1.0f : 4.0f, y, z}, {s, 0, 0}));
        rays.push_back(makeRay({0.0f, y, z}, {0, s, 0}));  // lying in the plane x = 0
        rays.push_back(makeRay({1.0f, y, z}, {0, 0, s}));  // lying in the plane x = 1
        rays.push_back(makeRay({2.5f, y, z}, {s, 0, 0}, 0.0f, 0.5f));  // ends exactly on x = 2 or 3
      }
  const Reference ref = bruteForce(g, rays);
  expectMatchesBruteForce(g, rays, generated, ref, allConfigs());
}

// One accelerator's configurations against brute force on the hard cases and
// part of the Cornell box with the bunny: the task tests of A4.2-A4.4 (each
// grades only its own structure; A4_Accelerators checks them all at once).
void expectAcceleratorMatchesBruteForce(const std::string& name) {
  std::vector<Config> configs;
  for (const Config& c : allConfigs())
    if (c.accelerator == name) configs.push_back(c);
  ASSERT_FALSE(configs.empty());
  const Geometry g = hardCases();
  const std::vector<Ray> rays = makeRays(g, 20000, 11);
  expectMatchesBruteForce(g, rays, rays.size(), bruteForce(g, rays), configs);
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/cornell_bunny.json");
  const std::vector<Ray> sceneRays = makeRays(scene.geometry, 8000, 12);
  expectMatchesBruteForce(scene.geometry, sceneRays, sceneRays.size(), bruteForce(scene.geometry, sceneRays), configs);
}

TEST(A4_2_Traversal, MatchesBruteForceOnHardCasesAndTheCornellBunny) { expectAcceleratorMatchesBruteForce("bvh"); }
TEST(A4_3_KdTraversal, MatchesBruteForceOnHardCasesAndTheCornellBunny) { expectAcceleratorMatchesBruteForce("kdtree"); }
TEST(A4_4_OctreeTraversal, MatchesBruteForceOnHardCasesAndTheCornellBunny) {
  expectAcceleratorMatchesBruteForce("octree");
}
TEST(A4_5_BspTraversal, MatchesBruteForceOnHardCasesAndTheCornellBunny) { expectAcceleratorMatchesBruteForce("bsp"); }

TEST(A4_Accelerators, EmptySceneAndSinglePrimitive) {
  Geometry empty;
  Geometry one;
  addSphere(one, {0, 0, 0}, 1.0f);
  for (const Config& c : allConfigs()) {
    SCOPED_TRACE(c.label());
    QueryCounters counters;
    Hit h;
    const auto a = make(c, empty);
    EXPECT_FALSE(a->intersect(makeRay({0, 0, -5}, {0, 0, 1}), h, counters));
    EXPECT_FALSE(h.valid());
    EXPECT_FALSE(a->occluded(makeRay({0, 0, -5}, {0, 0, 1}), counters));
    const auto b = make(c, one);
    ASSERT_TRUE(b->intersect(makeRay({0, 0, -5}, {0, 0, 1}), h, counters));
    EXPECT_EQ(h.prim, 0u);
    EXPECT_NEAR(h.t, 4.0f, 1e-5f);
    EXPECT_TRUE(b->occluded(makeRay({0, 0, 0}, {0, 1, 0}), counters));  // from inside
  }
}

// --- The BVH's structure and statistics ---------------------------------------------

Geometry bunny() { return loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/bunny.json").geometry; }

bool contains(const a4::BvhNode& outer, const Bounds3& inner) {
  return glm::all(glm::lessThanEqual(outer.lo, inner.min)) && glm::all(glm::greaterThanEqual(outer.hi, inner.max));
}

// Every primitive in exactly one leaf, boxes nested, leaves no larger than max_leaf.
void expectWellFormed(const a4::FlatBvh& bvh, const Geometry& g, int maxLeaf) {
  std::vector<int> seen(g.primitiveCount(), 0);
  for (size_t i = 0; i < bvh.nodes.size(); ++i) {
    const a4::BvhNode& n = bvh.nodes[i];
    if (n.isLeaf()) {
      EXPECT_LE(n.count, static_cast<uint32_t>(maxLeaf));
      for (uint32_t s = n.offset; s < n.offset + n.count; ++s) {
        ++seen[bvh.primIds[s]];
        EXPECT_TRUE(contains(n, g.bounds(bvh.primIds[s])));
      }
    } else {
      ASSERT_LT(n.offset, bvh.nodes.size());
      for (size_t child : {i + 1, size_t{n.offset}}) {
        Bounds3 b;
        b.min = bvh.nodes[child].lo;
        b.max = bvh.nodes[child].hi;
        EXPECT_TRUE(contains(n, b));
      }
    }
  }
  for (uint32_t p = 0; p < g.primitiveCount(); ++p) EXPECT_EQ(seen[p], 1) << "primitive " << p;
}

TEST(A4_1_Bvh, EverySplitMethodBuildsAWellFormedTree) {
  const Geometry g = bunny();
  ASSERT_TRUE(bvhImplemented(g));
  const Geometry h = hardCases();
  for (auto method : {a4::SplitMethod::Median, a4::SplitMethod::EqualCounts, a4::SplitMethod::Sah})
    for (int maxLeaf : {1, 4, 16}) {
      a4::SplitSettings s;
      s.method = method;
      s.maxLeaf = maxLeaf;
      SCOPED_TRACE(std::to_string(int(method)) + " max_leaf=" + std::to_string(maxLeaf));
      a4::BvhBuildInfo info;
      const a4::FlatBvh bvh = a4::buildBvh(g, s, a4::BoundingVolume::Box, &info);
      expectWellFormed(bvh, g, maxLeaf);
      EXPECT_LE(info.depth, a4::kBvhMaxDepth);
      EXPECT_LT(info.depth, 64);
      expectWellFormed(a4::buildBvh(h, s, a4::BoundingVolume::Box), h, maxLeaf);
    }
}

TEST(A4_1_Bvh, StatisticsAndTheSahPaysOff) {
  const Geometry g = bunny();
  auto statsOf = [&](const std::string& split, const std::string& volume) {
    return make({"bvh", {"split=" + split, "volume=" + volume}}, g)->stats();
  };
  const AcceleratorStats sah = statsOf("sah", "box"), median = statsOf("median", "box"),
                         equal = statsOf("equal-counts", "box"), sphere = statsOf("sah", "sphere");
  EXPECT_GT(sah.nodeCount, g.primitiveCount() / 4);
  EXPECT_LT(sah.nodeCount, 2 * size_t{g.primitiveCount()});
  EXPECT_GE(sah.memoryBytes, sah.nodeCount * sizeof(a4::BvhNode));
  EXPECT_GT(sah.depth, 5);
  EXPECT_GT(sah.sahCost, 1.0);
  EXPECT_GE(sah.buildSeconds, 0.0);
  if (bvhImplemented(g)) {
    EXPECT_LE(sah.sahCost, median.sahCost);
    EXPECT_LE(sah.sahCost, equal.sahCost);
    EXPECT_GT(sphere.sahCost, sah.sahCost);  // spheres fit triangles more loosely than boxes
  }
}

// --- Complexity: work per ray grows like log n ----------------------------------------

Geometry sphereMesh(int rings) {  // a UV sphere of about 4 rings^2 triangles
  Geometry g;
  const int segments = 2 * rings;
  auto at = [&](int i, int j) {
    const float theta = kPi * float(i) / float(rings), phi = 2.0f * kPi * float(j) / float(segments);
    return Vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
  };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const Vec3 a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if (i > 0) addTriangle(g, a, b, d);
      if (i < rings - 1) addTriangle(g, b, c, d);
    }
  return g;
}

// Counted work (nodes visited, primitives tested) per ray, never time.
std::pair<double, double> workPerRay(const Geometry& g, const Config& config) {
  const auto a = make(config, g);
  std::mt19937 rng(5);
  QueryCounters c;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const Vec3 o = 3.0f * randomDirection(rng);
    const Vec3 target = 0.5f * randomDirection(rng);
    Hit h;
    a->intersect(makeRay(o, target - o), h, c);
  }
  return {double(c.nodesVisited) / n, double(c.primitivesTested) / n};
}

TEST(A4_1_Bvh, NodesVisitedGrowLogarithmically) {
  const Geometry small = sphereMesh(24), large = sphereMesh(192);  // 2.3k and 147k triangles: 64x
  ASSERT_TRUE(bvhImplemented(small));
  ASSERT_GT(large.primitiveCount(), 60 * small.primitiveCount());
  auto perRay = [](const Geometry& g, const std::string& split) { return workPerRay(g, {"bvh", {"split=" + split}}); };
  for (const char* split : {"median", "equal-counts", "sah"}) {
    const auto [nodesSmall, primsSmall] = perRay(small, split);
    const auto [nodesLarge, primsLarge] = perRay(large, split);
    std::printf("[ %s ] per ray: %.1f -> %.1f nodes, %.1f -> %.1f primitives\n", split, nodesSmall, nodesLarge,
                primsSmall, primsLarge);
    // log(147k) / log(2.3k) = 1.5; linear growth would be 64, square-root growth 8.
    EXPECT_LT(nodesLarge / nodesSmall, 2.5) << split << ": " << nodesSmall << " -> " << nodesLarge << " nodes/ray";
    EXPECT_LT(primsLarge / primsSmall, 2.5) << split << ": " << primsSmall << " -> " << primsLarge << " prims/ray";
  }
}

// --- The student tasks -------------------------------------------------------------

std::vector<a4::BuildPrim> buildPrims(const Geometry& g) {
  std::vector<a4::BuildPrim> prims(g.primitiveCount());
  for (uint32_t p = 0; p < g.primitiveCount(); ++p) prims[p] = {g.bounds(p), g.centroid(p), p};
  return prims;
}

TEST(A4_1_Split, PartitionsEveryMethodAndHonoursMaxLeaf) {
  const Geometry g = bunny();
  std::vector<a4::BuildPrim> prims = buildPrims(g);
  Bounds3 all;
  for (const auto& p : prims) all.extend(p.bounds);
  ASSERT_TRUE(implemented("A4.1", [&] { a4::splitPrimitives(prims, all, a4::SplitSettings{}); }));
  for (auto method : {a4::SplitMethod::Median, a4::SplitMethod::EqualCounts, a4::SplitMethod::Sah}) {
    a4::SplitSettings s;
    s.method = method;
    const size_t k = a4::splitPrimitives(prims, all, s);
    EXPECT_GT(k, 0u);
    EXPECT_LT(k, prims.size());
    if (method == a4::SplitMethod::EqualCounts) {
      EXPECT_EQ(k, prims.size() / 2);
    }
    std::vector<int> seen(prims.size(), 0);  // still a permutation
    for (const auto& p : prims) ++seen[p.prim];
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(prims.size()));
    // Identical centroids: still split while above max_leaf, a leaf at or below it.
    std::vector<a4::BuildPrim> same(10, prims[0]);
    s.maxLeaf = 4;
    const size_t kSame = a4::splitPrimitives(same, prims[0].bounds, s);
    EXPECT_TRUE(kSame > 0 && kSame < same.size());
    std::vector<a4::BuildPrim> few(3, prims[0]);
    EXPECT_EQ(a4::splitPrimitives(few, prims[0].bounds, s), 0u);
  }
}

TEST(A4_1_Split, SahSeparatesAClusterFromAnOutlier) {
  // 100 tiny boxes near the origin and one far away: the SAH cuts off the outlier's
  // empty space, where the spatial median would too -- but equal counts would not.
  std::vector<a4::BuildPrim> prims;
  Bounds3 all;
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (uint32_t i = 0; i <= 100; ++i) {
    const Vec3 c = i < 100 ? Vec3(u(rng), u(rng), u(rng)) : Vec3(100.0f, 0.5f, 0.5f);
    Bounds3 b;
    b.extend(c - Vec3(0.01f));
    b.extend(c + Vec3(0.01f));
    prims.push_back({b, c, i});
    all.extend(b);
  }
  a4::SplitSettings s;
  ASSERT_TRUE(implemented("A4.1", [&] { a4::splitPrimitives(prims, all, s); }));
  const size_t k = a4::splitPrimitives(prims, all, s);
  const bool outlierAlone = (k == 100 && prims[100].prim == 100) || (k == 1 && prims[0].prim == 100);
  EXPECT_TRUE(outlierAlone) << "k = " << k;
}

TEST(A4_1_Split, SahFindsTheCheapestSplitByTheSurfaceAreaOfTheChildren) {
  // Twelve flat boxes (like triangles: one extent zero) with centroids at x = 0..11, y = z = 0, so
  // the only axis to split is x and every centroid has its own bin: the binned SAH must find the
  // exact optimum of A_left * N_left + A_right * N_right over the 11 cuts. (A "SAH" by volume
  // sees every flat child as free and cuts anywhere.)
  const auto halfArea = [](const Bounds3& b) { return b.halfSurfaceArea(); };
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.05f, 3.0f);
  int differentFromMedian = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<a4::BuildPrim> prims;
    Bounds3 all;
    for (uint32_t i = 0; i < 12; ++i) {
      Vec3 half(0.4f * u(rng) / 3.0f, u(rng), u(rng));
      half[static_cast<int>(rng() % 3)] = 0.0f;
      const Vec3 c(static_cast<float>(i), 0.0f, 0.0f);
      Bounds3 b;
      b.extend(c - half);
      b.extend(c + half);
      prims.push_back({b, c, i});
      all.extend(b);
    }
    std::vector<float> costOf(12, 0.0f);  // cost of cutting after the k lowest x
    for (size_t k = 1; k < 12; ++k) {
      Bounds3 l, r;
      for (size_t i = 0; i < 12; ++i) (i < k ? l : r).extend(prims[i].bounds);
      costOf[k] = halfArea(l) * static_cast<float>(k) + halfArea(r) * static_cast<float>(12 - k);
    }
    const float best = *std::min_element(costOf.begin() + 1, costOf.end());
    a4::SplitSettings s;
    s.maxLeaf = 1;
    ASSERT_TRUE(implemented("A4.1", [&] { a4::splitPrimitives(prims, all, s); }));
    std::shuffle(prims.begin(), prims.end(), rng);
    const size_t k = a4::splitPrimitives(prims, all, s);
    ASSERT_TRUE(k > 0 && k < 12) << "k = " << k;
    for (size_t i = 0; i < 12; ++i) ASSERT_EQ(prims[i].prim < k, i < k) << "not a cut along x (trial " << trial << ")";
    EXPECT_LE(costOf[k], best * (1.0f + 1e-5f)) << "trial " << trial << ": cut after " << k << " costs " << costOf[k]
                                                 << ", the best " << best;
    if (k != 6) ++differentFromMedian;
  }
  EXPECT_GT(differentFromMedian, 0);  // the configurations do test the heuristic
}

TEST(A4_2_Traversal, VisitsFewNodesAndStopsAtTheFirstOccluder) {
  const Geometry g = bunny();
  const auto bvh = make({"bvh", {}}, g);
  const Ray ray = makeRay(g.sceneBounds().center() + Vec3(0, 0, 10), {0, 0, -1});
  Hit h;
  QueryCounters c;
  ASSERT_TRUE(implemented("A4.2", [&] { bvh->intersect(ray, h, c); }));
  ASSERT_TRUE(implemented("A4.2", [&] { bvh->occluded(ray, c); }));
  QueryCounters closest, any;
  std::mt19937 rng(3);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 o = g.sceneBounds().center() + 2.0f * g.sceneBounds().diagonal() * randomDirection(rng);
    const Ray r = makeRay(o, g.sceneBounds().center() - o);
    bvh->intersect(r, h, closest);
    bvh->occluded(r, any);
  }
  EXPECT_LT(closest.primitivesTested, 1000u * g.primitiveCount() / 50);  // far from brute force
  EXPECT_GT(closest.nodesVisited, 1000u);
  EXPECT_LT(any.nodesVisited, closest.nodesVisited);  // any hit stops early
}

TEST(A4_Stubs, BvhStaysCorrectWhateverIsMissing) {
  // With the stubs (student tree) the accelerator must still answer like brute force;
  // with the solution this is a plain check. Either way: no crash, same hits.
  const Geometry g = bunny();
  const std::vector<Ray> rays = makeRays(g, 2000, 11);
  const Reference ref = bruteForce(g, rays);
  TaskLog log;
  const ScopedTaskLog scope(&log);
  expectMatchesBruteForce(g, rays, rays.size(), ref, {Config{"bvh", {}}});
  for (const auto& [id, what] : log.missing()) EXPECT_TRUE(id == "A4.1" || id == "A4.2") << id;
}


// --- The KD-tree and the octree: structure, statistics, complexity, tasks ---------------

// Every primitive is referenced by the leaf cells its box touches (at least
// one), and every referenced primitive's box touches its leaf's cell.
template <class Shapes>
void expectCellsCoverPrimitives(const Shapes& leaves, const Geometry& g, size_t slots) {
  size_t total = 0;
  for (const NodeShape& s : leaves) EXPECT_TRUE(s.leaf);
  std::vector<int> touched(g.primitiveCount(), 0);
  for (uint32_t p = 0; p < g.primitiveCount(); ++p) {
    const Bounds3 b = g.bounds(p);
    for (const NodeShape& s : leaves)
      if (glm::all(glm::lessThanEqual(b.min, s.box.max)) && glm::all(glm::greaterThanEqual(b.max, s.box.min)))
        ++touched[p];
    EXPECT_GE(touched[p], 1) << "primitive " << p << " lies in no leaf cell";
    total += static_cast<size_t>(touched[p]);
  }
  EXPECT_GE(total, slots);  // no leaf holds a primitive whose box misses its cell
}

TEST(A4_KdTree, WellFormedWithPlanarPrimitivesAndStatistics) {
  const Geometry h = hardCases();
  a4::KdBuildInfo info;
  const a4::KdTree tree = a4::buildKdTree(h, a4::KdSettings{}, &info);
  ASSERT_FALSE(tree.nodes.empty());
  std::vector<int> seen(h.primitiveCount(), 0);
  for (const a4::KdNode& n : tree.nodes) {
    if (!n.isLeaf()) {
      EXPECT_LT(n.aboveChild(), tree.nodes.size());
      continue;
    }
    for (uint32_t s = n.first(); s < n.first() + n.count(); ++s) ++seen[tree.primIds[s]];
  }
  for (uint32_t p = 0; p < h.primitiveCount(); ++p) EXPECT_GE(seen[p], 1) << "primitive " << p;
  EXPECT_LE(info.depth, a4::kKdMaxDepth);
  EXPECT_GE(info.leafSlots, h.primitiveCount());
  const auto accel = make({"kdtree", {}}, h);
  const auto leaves = accel->nodesAtDepth(1000);  // every leaf
  expectCellsCoverPrimitives(leaves, h, info.leafSlots);
  EXPECT_EQ(accel->nodesAtDepth(0).size(), 1u);
  EXPECT_EQ(accel->nodesAtDepth(1).size(), 2u);

  const Geometry g = bunny();
  const AcceleratorStats st = make({"kdtree", {}}, g)->stats();
  EXPECT_GT(st.nodeCount, g.primitiveCount() / 4);
  EXPECT_GE(st.memoryBytes, st.nodeCount * sizeof(a4::KdNode) + g.primitiveCount() * sizeof(uint32_t));
  EXPECT_GT(st.depth, 5);
  EXPECT_GT(st.sahCost, 1.0);
  EXPECT_GE(st.buildSeconds, 0.0);
}

// The sweep build (Wald and Havran 2006) prices every face of every box where the binned build prices 31
// planes per axis: on meshes its trees are as cheap under the SAH or cheaper (1 % slack for the greedy
// choice). Both builds' parallel subtrees make the same tree on any number of threads (the hard cases too).
TEST(A4_KdTree, SweepBuildMakesTreesAsCheapAsTheBinnedBuildOnAnyThreadCount) {
  const Geometry cornellBunny = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/cornell_bunny.json").geometry;
  for (const Geometry* mesh : {&cornellBunny, static_cast<const Geometry*>(nullptr)}) {
    const Geometry g = mesh ? *mesh : hardCases();
    a4::KdSettings sweep, binned;
    binned.build = a4::KdBuild::Binned;
    a4::KdBuildInfo sweepInfo, binnedInfo;
    const a4::KdTree sweepTree = a4::buildKdTree(g, sweep, &sweepInfo);
    const a4::KdTree binnedTree = a4::buildKdTree(g, binned, &binnedInfo);
    if (mesh) {
      EXPECT_LE(sweepInfo.sahCost, 1.01 * binnedInfo.sahCost);
      EXPECT_GT(sweepInfo.sahCost, 0.5 * binnedInfo.sahCost);  // the same measure, not another one
    }
    const tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
    for (const auto& [settings, tree] : {std::pair{sweep, &sweepTree}, std::pair{binned, &binnedTree}}) {
      const a4::KdTree serial = a4::buildKdTree(g, settings);
      ASSERT_EQ(serial.nodes.size(), tree->nodes.size());
      for (size_t i = 0; i < tree->nodes.size(); ++i) {
        ASSERT_EQ(serial.nodes[i].word, tree->nodes[i].word) << "node " << i;
        ASSERT_EQ(serial.nodes[i].bits, tree->nodes[i].bits) << "node " << i;
      }
      EXPECT_EQ(serial.primIds, tree->primIds);
    }
  }
}

TEST(A4_Octree, WellFormedAndStatistics) {
  const Geometry h = hardCases();
  a4::OctreeSettings s;
  s.maxDepth = 5;
  s.maxLeaf = 2;
  a4::OctreeBuildInfo info;
  const a4::Octree tree = a4::buildOctree(h, s, &info);
  ASSERT_FALSE(tree.nodes.empty());
  EXPECT_EQ((tree.nodes.size() - 1) % 8, 0u);
  EXPECT_LE(info.depth, 5);
  const auto accel = make({"octree", {"max_depth=5", "max_leaf=2"}}, h);
  expectCellsCoverPrimitives(accel->nodesAtDepth(1000), h, info.leafSlots);
  EXPECT_EQ(accel->nodesAtDepth(0).size(), 1u);
  EXPECT_LE(accel->nodesAtDepth(1).size(), 8u);

  const Geometry g = bunny();
  const AcceleratorStats st = make({"octree", {}}, g)->stats();
  EXPECT_GT(st.nodeCount, 64u);
  EXPECT_GE(st.memoryBytes, st.nodeCount * sizeof(a4::OctreeNode) + g.primitiveCount() * sizeof(uint32_t));
  EXPECT_GT(st.depth, 3);
  EXPECT_GT(st.sahCost, 1.0);
}

// A sphere made of a cube's six faces, k x k quads each, pushed out onto the
// unit sphere: 12 k^2 triangles, no vertex shared by more than six (a UV
// sphere's poles are shared by 4 rings triangles: a cell holding a pole holds
// them all, however small -- a worst case for space subdivision, not a test
// of how the work grows).
Geometry cubeSphere(int k) {
  Geometry g;
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {-1.0f, 1.0f}) {
      auto at = [&](int i, int j) {
        Vec3 p;
        p[axis] = side;
        p[(axis + 1) % 3] = 2.0f * float(i) / float(k) - 1.0f;
        p[(axis + 2) % 3] = 2.0f * float(j) / float(k) - 1.0f;
        return glm::normalize(p);
      };
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
          addTriangle(g, at(i, j), at(i + 1, j), at(i + 1, j + 1));
          addTriangle(g, at(i, j), at(i + 1, j + 1), at(i, j + 1));
        }
    }
  return g;
}

TEST(A4_SpaceSubdivision, NodesVisitedGrowLogarithmically) {
  const Geometry small = cubeSphere(14), large = cubeSphere(112);  // 2.4k and 151k triangles: 64x
  for (const char* name : {"kdtree", "octree"}) {
    const char* task = std::string(name) == "kdtree" ? "A4.3" : "A4.4";
    if (!taskImplemented(small, name, task)) {
      ADD_FAILURE() << task << " not implemented";
      continue;
    }
    // The octree's depth limit must not cap the large mesh: let it go two levels deeper.
    const Config cs{name, {}}, cl{name, std::string(name) == "octree" ? std::vector<std::string>{"max_depth=10"}
                                                                        : std::vector<std::string>{}};
    const auto [nodesSmall, primsSmall] = workPerRay(small, cs);
    const auto [nodesLarge, primsLarge] = workPerRay(large, cl);
    std::printf("[ %s ] per ray: %.1f -> %.1f nodes, %.1f -> %.1f primitives\n", name, nodesSmall, nodesLarge,
                primsSmall, primsLarge);
    EXPECT_LT(nodesLarge / nodesSmall, 2.5) << name << ": " << nodesSmall << " -> " << nodesLarge << " nodes/ray";
    EXPECT_LT(primsLarge / primsSmall, 2.5) << name << ": " << primsSmall << " -> " << primsLarge << " prims/ray";
  }
}

// A4.3 and A4.4: few nodes and primitives, and any hit stops early.
void expectTraversalWork(const std::string& name, const char* task) {
  const Geometry g = bunny();
  const auto accel = make({name, {}}, g);
  const Ray ray = makeRay(g.sceneBounds().center() + Vec3(0, 0, 10), {0, 0, -1});
  Hit h;
  QueryCounters c;
  ASSERT_TRUE(implemented(task, [&] { accel->intersect(ray, h, c); }));
  ASSERT_TRUE(implemented(task, [&] { accel->occluded(ray, c); }));
  QueryCounters closest, any;
  std::mt19937 rng(3);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 o = g.sceneBounds().center() + 2.0f * g.sceneBounds().diagonal() * randomDirection(rng);
    const Ray r = makeRay(o, g.sceneBounds().center() - o);
    accel->intersect(r, h, closest);
    accel->occluded(r, any);
  }
  EXPECT_LT(closest.primitivesTested, 1000u * g.primitiveCount() / 50);  // far from brute force
  EXPECT_GT(closest.nodesVisited, 1000u);
  EXPECT_LE(any.nodesVisited, closest.nodesVisited);  // any hit stops early
}

TEST(A4_3_KdTraversal, VisitsFewNodesAndStopsAtTheFirstOccluder) { expectTraversalWork("kdtree", "A4.3"); }
TEST(A4_4_OctreeTraversal, VisitsFewNodesAndStopsAtTheFirstOccluder) { expectTraversalWork("octree", "A4.4"); }
TEST(A4_5_BspTraversal, VisitsFewNodesAndStopsAtTheFirstOccluder) { expectTraversalWork("bsp", "A4.5"); }

// A ray in a split plane: the triangles on both sides of the plane count (each accelerator's
// configurations; the test of A4.2, A4.3 or A4.4 checks only its own structure).
void expectSplitPlaneRaysSeeBothSides(const std::string& accelerator) {
  Geometry g;
  // Two walls of the same cell boundary x = 1 seen edge-on, and a far wall.
  addQuad(g, {1, 0, 2}, {-0.5f, 0, 0}, {0, 1, 0});  // below the plane x = 1, touching it
  addQuad(g, {1, 0, 1}, {0.5f, 0, 0}, {0, 1, 0});   // above it, touching it, nearer
  addQuad(g, {0, 0, 5}, {2, 0, 0}, {0, 1, 0});
  for (int i = 0; i < 40; ++i) addTriangle(g, {0.1f * float(i % 10), 3, 0}, {0.1f * float(i % 10) + 0.05f, 3, 0}, {0.1f * float(i % 10), 3.05f, 0.1f * float(i / 10)});
  const Ray ray = makeRay({1, 0.5f, 0}, {0, 0, 1});
  Hit ref;
  QueryCounters c;
  make({"none", {}}, g)->intersect(ray, ref, c);
  ASSERT_TRUE(ref.valid());
  for (const Config& config : allConfigs()) {
    if (!config.exact() || config.accelerator != accelerator) continue;
    SCOPED_TRACE(config.label());
    Hit h;
    make(config, g)->intersect(ray, h, c);
    EXPECT_TRUE(h.prim == ref.prim && h.t == ref.t)
        << "the ray from (1, 0.5, 0) along +z lies in the plane x = 1: got " << testing_support::describeHit(h)
        << ", brute force " << testing_support::describeHit(ref) << " (the wall touching x = 1 from above)";
  }
}

TEST(A4_2_Traversal, RaysInASplitPlaneSeeBothSides) { expectSplitPlaneRaysSeeBothSides("bvh"); }
TEST(A4_3_KdTraversal, RaysInTheSplitPlaneSeeBothSides) { expectSplitPlaneRaysSeeBothSides("kdtree"); }
TEST(A4_4_OctreeTraversal, RaysInASplitPlaneSeeBothSides) { expectSplitPlaneRaysSeeBothSides("octree"); }
TEST(A4_5_BspTraversal, RaysInASplitPlaneSeeBothSides) { expectSplitPlaneRaysSeeBothSides("bsp"); }

// The BSP tree's own planes: a mesh whose triangles lean at every angle (a sphere) is cut by some of
// them, every primitive lies in a leaf, and the leaves' convex cells tile the scene's box: their
// volumes (divergence theorem over their faces) add up to the box's.
TEST(A4_Bsp, CutsByTrianglePlanesAndItsCellsTileTheScene) {
  const Geometry g = cubeSphere(8);
  a4::BspSettings s;
  s.triangleCandidates = 16;
  a4::BspBuildInfo info;
  const a4::BspTree tree = a4::buildBspTree(g, s, &info);
  EXPECT_GT(info.trianglePlanes, 0u);
  EXPECT_GT(info.axisPlanes, 0u);
  const size_t interior = info.trianglePlanes + info.axisPlanes;
  EXPECT_EQ(info.nodeCount, 2 * interior + 1);  // a binary tree
  size_t axisNodes = 0;  // interior nodes that say their plane is x[axis] = offset, and are
  for (const a4::BspNode& n : tree.nodes) {
    if (n.isLeaf() || n.axis() == a4::BspNode::kAnyPlane) continue;
    ++axisNodes;
    Vec3 unit(0.0f);
    unit[n.axis()] = 1.0f;
    EXPECT_EQ(n.normal, unit);
  }
  EXPECT_GE(axisNodes, info.axisPlanes);  // (a triangle's plane may be one too)
  EXPECT_LT(axisNodes, interior);
  std::vector<int> seen(g.primitiveCount(), 0);
  for (const a4::BspNode& n : tree.nodes)
    if (n.isLeaf())
      for (uint32_t k = n.first(); k < n.first() + n.count(); ++k) ++seen[tree.primIds[k]];
  for (uint32_t p = 0; p < g.primitiveCount(); ++p) EXPECT_GE(seen[p], 1) << "primitive " << p;

  const auto volume = [](const a4::ConvexCell& cell) {
    double v = 0.0;
    for (const auto& f : cell.faces())
      for (size_t i = 1; i + 1 < f.size(); ++i) v += static_cast<double>(glm::dot(f[0], glm::cross(f[i], f[i + 1])));
    return v / 6.0;
  };
  const a4::ConvexCell root = a4::ConvexCell::box(tree.bounds);
  double leaves = 0.0;
  std::vector<std::pair<uint32_t, a4::ConvexCell>> stack{{0u, root}};
  while (!stack.empty()) {
    auto [index, cell] = std::move(stack.back());
    stack.pop_back();
    const a4::BspNode& n = tree.nodes[index];
    if (n.isLeaf()) {
      leaves += volume(cell);
      continue;
    }
    a4::ConvexCell below, above;
    cell.split(n.normal, n.offset, below, above);
    if (!below.empty()) stack.emplace_back(index + 1, std::move(below));
    if (!above.empty()) stack.emplace_back(n.aboveChild(), std::move(above));
  }
  EXPECT_NEAR(leaves, volume(root), 1e-3 * volume(root));

  const auto accel = make({"bsp", {"triangle_planes=16"}}, g);
  EXPECT_EQ(accel->nodesAtDepth(0).size(), 1u);
  EXPECT_EQ(accel->nodesAtDepth(1).size(), 2u);
  for (const NodeShape& c : accel->nodesAtDepth(4)) EXPECT_GE(c.edges.size(), 12u);  // at least a tetrahedron's 4 x 3
}

// The BSP build's subtrees built apart (nodes of 8192 primitives or more, in parallel) are spliced into
// one well-formed tree -- every above child after its node, the leaves' slot ranges tiling the slots
// in order, every primitive in a leaf -- and make the same tree on one thread as on all: node for node,
// the same slots and statistics (a 19k-triangle sphere: its top levels are built apart).
TEST(A4_Bsp, SplicedSubtreesMakeOneTreeTheSameOnAnyThreadCount) {
  const Geometry g = cubeSphere(40);
  ASSERT_GE(g.primitiveCount(), 2u * 8192u);
  a4::BspBuildInfo info, serialInfo;
  const a4::BspTree tree = a4::buildBspTree(g, {}, &info);
  uint32_t nextSlot = 0;  // depth-first order writes the leaves' slots in order
  std::vector<int> seen(g.primitiveCount(), 0);
  for (size_t i = 0; i < tree.nodes.size(); ++i) {
    const a4::BspNode& n = tree.nodes[i];
    if (!n.isLeaf()) {
      ASSERT_GT(n.aboveChild(), i + 1) << "node " << i;
      ASSERT_LT(n.aboveChild(), tree.nodes.size()) << "node " << i;
      continue;
    }
    ASSERT_EQ(n.first(), nextSlot) << "node " << i;
    nextSlot += n.count();
    ASSERT_LE(nextSlot, tree.primIds.size());
    for (uint32_t k = n.first(); k < nextSlot; ++k) ++seen[tree.primIds[k]];
  }
  EXPECT_EQ(nextSlot, tree.primIds.size());
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 0), 0) << "primitives in no leaf";
  const tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
  const a4::BspTree serial = a4::buildBspTree(g, {}, &serialInfo);
  ASSERT_EQ(serial.nodes.size(), tree.nodes.size());
  for (size_t i = 0; i < tree.nodes.size(); ++i)
    ASSERT_EQ(std::memcmp(&serial.nodes[i], &tree.nodes[i], sizeof(a4::BspNode)), 0) << "node " << i;
  EXPECT_EQ(serial.primIds, tree.primIds);
  EXPECT_EQ(serialInfo.depth, info.depth);
  EXPECT_EQ(serialInfo.trianglePlanes, info.trianglePlanes);
  EXPECT_EQ(serialInfo.axisPlanes, info.axisPlanes);
  EXPECT_NEAR(serialInfo.sahCost, info.sahCost, 1e-9 * info.sahCost);  // (sums in another order)
}

TEST(A4_Stubs, KdTreeAndOctreeStayCorrectWhateverIsMissing) {
  const Geometry g = bunny();
  const std::vector<Ray> rays = makeRays(g, 2000, 11);
  const Reference ref = bruteForce(g, rays);
  TaskLog log;
  const ScopedTaskLog scope(&log);
  expectMatchesBruteForce(g, rays, rays.size(), ref, {Config{"kdtree", {}}, Config{"octree", {}}});
  for (const auto& [id, what] : log.missing()) EXPECT_TRUE(id == "A4.3" || id == "A4.4") << id;
}

}  // namespace
}  // namespace ll
