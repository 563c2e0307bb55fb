// Assignment 2 (ray casting): the five student tasks against closed-form
// answers, and whole renders of the analytic test scenes.
//
// Every task suite checks first that the task is implemented: its fixture's
// SetUp() calls the function with a TaskLog installed, and a stub (which
// reports itself through LIGHTLAB_TODO) fails the test with "A2.x not
// implemented (...)" before any value is checked. So with LIGHTLAB_SOLUTION=0
// this file compiles and every task test fails with that message, instead of
// passing on the framework fallbacks or failing with misleading numbers.
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render_support.h"
#include "test_support.h"
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "a2_tasks.h"
#include "accel/ray_sphere.h"
#include "accel/ray_triangle.h"
#include "modules/registry.h"
#include "render/render_job.h"
#include "render/student_task.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

using DVec3 = glm::dvec3;

const std::string kTestScenes = std::string(LIGHTLAB_DATA_DIR) + "/scenes/tests/";

using testing_support::implemented;

std::string missingTasks(const RenderStats& stats) {
  std::string out;
  for (const auto& [id, what] : stats.missingTasks) out += id + " not implemented (" + what + "); ";
  return out;
}

using testing_support::makeRay;

void expectVecNear(const Vec3& a, const Vec3& b, float tol, const std::string& what = "") {
  EXPECT_NEAR(a.x, b.x, tol) << what;
  EXPECT_NEAR(a.y, b.y, tol) << what;
  EXPECT_NEAR(a.z, b.z, tol) << what;
}

// Relative comparison per channel with an absolute floor.
void expectRgbRel(const Rgb& actual, const DVec3& expected, double rel, const std::string& what) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(static_cast<double>(actual[c]), expected[c], rel * std::abs(expected[c]) + 1e-6)
        << what << " channel " << c;
}

// =============================================================================
// A2.1 Camera rays
// =============================================================================

class A2_1_CameraRay : public testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(implemented("A2.1", [] { (void)a2::cameraRay(Camera{}, 1.0f, 1.0f); }));
  }
  // A camera in general position, wider than tall.
  static Camera camera() {
    Camera c;
    c.eye = Vec3(1.0f, 2.0f, 3.0f);
    c.target = Vec3(-2.0f, 0.5f, 1.0f);
    c.up = Vec3(0.1f, 1.0f, 0.2f);  // not perpendicular to the view direction
    c.fovYDeg = 50.0f;
    c.width = 80;
    c.height = 60;
    return c;
  }
  // The camera frame in double, from the definitions in a2_tasks.h.
  struct DFrame {
    DVec3 u, v, w;
  };
  static DFrame frame(const Camera& c) {
    DFrame f;
    f.w = glm::normalize(DVec3(c.target) - DVec3(c.eye));
    f.u = glm::normalize(glm::cross(f.w, DVec3(c.up)));
    f.v = glm::cross(f.u, f.w);
    return f;
  }
};

TEST_F(A2_1_CameraRay, CentreRayIsViewDirection) {
  const Camera c = camera();
  const Ray r = a2::cameraRay(c, 40.0f, 30.0f);
  EXPECT_EQ(r.origin, c.eye);
  expectVecNear(r.dir, glm::normalize(c.target - c.eye), 1e-6f);
  EXPECT_NEAR(glm::length(r.dir), 1.0f, 1e-6f);
}

TEST_F(A2_1_CameraRay, CornersMatchTheFieldOfView) {
  const Camera c = camera();
  const DFrame f = frame(c);
  const double t = std::tan(50.0 * 3.14159265358979323846 / 360.0);
  const double aspect = 80.0 / 60.0;
  struct Corner {
    float px, py;
    double right, up;  // expected tangents along u and v
  } corners[] = {{0, 0, -aspect * t, t}, {80, 0, aspect * t, t}, {0, 60, -aspect * t, -t}, {80, 60, aspect * t, -t}};
  for (const Corner& k : corners) {
    const Ray r = a2::cameraRay(c, k.px, k.py);
    const DVec3 d(r.dir);
    EXPECT_NEAR(glm::length(d), 1.0, 1e-6);
    EXPECT_EQ(r.origin, c.eye);
    const double forward = glm::dot(d, f.w);
    ASSERT_GT(forward, 0.0);
    EXPECT_NEAR(glm::dot(d, f.u) / forward, k.right, 1e-5) << k.px << "," << k.py;
    EXPECT_NEAR(glm::dot(d, f.v) / forward, k.up, 1e-5) << k.px << "," << k.py;
  }
}

TEST_F(A2_1_CameraRay, VerticalFieldOfViewIsVertical) {
  // The rays through the top and bottom edge centres are fovY apart, the left
  // and right edge centres 2 atan(aspect tan(fovY/2)) apart.
  const Camera c = camera();
  const DVec3 top(a2::cameraRay(c, 40.0f, 0.0f).dir), bottom(a2::cameraRay(c, 40.0f, 60.0f).dir);
  const DVec3 left(a2::cameraRay(c, 0.0f, 30.0f).dir), right(a2::cameraRay(c, 80.0f, 30.0f).dir);
  const double deg = 180.0 / 3.14159265358979323846;
  EXPECT_NEAR(std::acos(glm::dot(top, bottom)) * deg, 50.0, 1e-3);
  const double horizontal = 2.0 * std::atan(80.0 / 60.0 * std::tan(25.0 / deg)) * deg;
  EXPECT_NEAR(std::acos(glm::dot(left, right)) * deg, horizontal, 1e-3);
}

TEST_F(A2_1_CameraRay, ImageRightIsForwardCrossUpAndRowZeroIsTop) {
  // The Cornell box camera looks along +z with up +y: image right is -x.
  Camera c;
  c.eye = Vec3(278, 273, -800);
  c.target = Vec3(278, 273, 0);
  c.fovYDeg = 39.3076f;
  c.width = c.height = 64;
  const Ray right = a2::cameraRay(c, 60.0f, 32.0f);
  const Ray top = a2::cameraRay(c, 32.0f, 2.0f);
  EXPECT_LT(right.dir.x, -0.1f);
  EXPECT_NEAR(right.dir.y, 0.0f, 1e-6f);
  EXPECT_GT(top.dir.y, 0.1f);
  EXPECT_NEAR(top.dir.x, 0.0f, 1e-6f);
}

TEST_F(A2_1_CameraRay, AgreesWithReferenceCamera) {
  const Camera c = camera();
  const CameraFrame f(c);
  std::mt19937 gen = testing_support::gradingRng(1);
  std::uniform_real_distribution<float> px(0.0f, 80.0f), py(0.0f, 60.0f);
  for (int i = 0; i < 200; ++i) {
    const float x = px(gen), y = py(gen);
    const Ray mine = a2::cameraRay(c, x, y);
    const Ray ref = referenceCameraRay(c, f, x, y);
    expectVecNear(mine.origin, ref.origin, 0.0f);
    expectVecNear(mine.dir, ref.dir, 2e-6f, std::to_string(x) + "," + std::to_string(y));
  }
}

// =============================================================================
// A2.2 Ray-sphere
// =============================================================================

class A2_2_RaySphere : public testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(implemented("A2.2", [] {
      float t = 0.0f;
      (void)a2::raySphere(Ray{}, Sphere{}, t);
    }));
  }
  // Ray and sphere moved together by the grading seed's offset: the same t, inputs no table holds.
  static bool hit(const Ray& r, Vec3 c, float radius, float& t) {
    const Vec3 shift = testing_support::gradingOffset(22);
    Ray moved = r;
    moved.origin += shift;
    return a2::raySphere(moved, Sphere{c + shift, radius}, t);
  }
};

TEST_F(A2_2_RaySphere, HitFromOutside) {
  float t = 0.0f;
  ASSERT_TRUE(hit(makeRay({0, 0, 5}, {0, 0, -1}), Vec3(0.0f), 1.0f, t));
  EXPECT_FLOAT_EQ(t, 4.0f);
  ASSERT_TRUE(hit(makeRay({0.6f, 0, 5}, {0, 0, -1}), Vec3(0.0f), 1.0f, t));
  EXPECT_NEAR(t, 4.2f, 1e-6f);  // 5 - sqrt(1 - 0.6^2)
  ASSERT_TRUE(hit(makeRay({2, 3, 4}, {1, 0, 0}), Vec3(7, 3, 4), 2.0f, t));
  EXPECT_FLOAT_EQ(t, 3.0f);
}

TEST_F(A2_2_RaySphere, DirectionNeedNotBeUnit) {
  float t = 0.0f;
  ASSERT_TRUE(hit(makeRay({0, 0, 5}, {0, 0, -2}), Vec3(0.0f), 1.0f, t));
  EXPECT_FLOAT_EQ(t, 2.0f);
  ASSERT_TRUE(hit(makeRay({0, 0, 5}, {0, 0, -0.5f}), Vec3(0.0f), 1.0f, t));
  EXPECT_FLOAT_EQ(t, 8.0f);
}

TEST_F(A2_2_RaySphere, Misses) {
  float t = 0.0f;
  // (A control first: a test that always says "no hit" must not pass this.)
  ASSERT_TRUE(hit(makeRay({0.99f, 0, 5}, {0, 0, -1}), Vec3(0.0f), 1.0f, t)) << "a ray 0.01 inside the silhouette";
  EXPECT_FALSE(hit(makeRay({1.01f, 0, 5}, {0, 0, -1}), Vec3(0.0f), 1.0f, t));
  EXPECT_FALSE(hit(makeRay({0, 0, 5}, {0, 0, 1}), Vec3(0.0f), 1.0f, t));  // sphere behind
  EXPECT_FALSE(hit(makeRay({0, 0, 5}, {0, 1, 0}), Vec3(0.0f), 1.0f, t));
}

TEST_F(A2_2_RaySphere, FromInsideReturnsTheExit) {
  float t = 0.0f;
  ASSERT_TRUE(hit(makeRay({0, 0, 0}, {0, 1, 0}), Vec3(0.0f), 2.0f, t));
  EXPECT_FLOAT_EQ(t, 2.0f);
  ASSERT_TRUE(hit(makeRay({0.5f, 0, 0}, {-1, 0, 0}), Vec3(0.0f), 1.0f, t));
  EXPECT_FLOAT_EQ(t, 1.5f);
}

TEST_F(A2_2_RaySphere, RespectsTminAndTmax) {
  float t = 0.0f;
  const Vec3 o(0, 0, 5), d(0, 0, -1);
  EXPECT_FALSE(hit(makeRay(o, d, 0.0f, 3.5f), Vec3(0.0f), 1.0f, t));
  ASSERT_TRUE(hit(makeRay(o, d, 0.0f, 4.5f), Vec3(0.0f), 1.0f, t));
  EXPECT_FLOAT_EQ(t, 4.0f);
  ASSERT_TRUE(hit(makeRay(o, d, 4.5f), Vec3(0.0f), 1.0f, t));
  EXPECT_FLOAT_EQ(t, 6.0f);  // the near root is excluded: the far one
  EXPECT_FALSE(hit(makeRay(o, d, 6.5f), Vec3(0.0f), 1.0f, t));
}

TEST_F(A2_2_RaySphere, AgreesWithFrameworkOnRandomRays) {
  std::mt19937 gen = testing_support::gradingRng(3);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  const Vec3 c(0.3f, -0.2f, 0.1f);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 origin(u(gen), u(gen), u(gen));
    // Half the rays in a random direction, half aimed near the sphere.
    const Vec3 dir = i % 2 == 0 ? Vec3(u(gen), u(gen), u(gen)) : c + 0.7f * Vec3(u(gen), u(gen), u(gen)) - origin;
    const Ray r = makeRay(origin, dir);
    // Skip rays within 1e-3 of tangent: either answer is acceptable there.
    const DVec3 o(r.origin), d(r.dir);
    const double tc = glm::dot(DVec3(c) - o, d) / glm::dot(d, d);
    if (std::abs(glm::length(o + tc * d - DVec3(c)) - 1.5) < 1e-3) continue;
    float tMine = 0.0f, tRef = 0.0f;
    const bool mine = hit(r, c, 1.5f, tMine);
    Ray moved = r;
    moved.origin += testing_support::gradingOffset(22);
    const bool ref = intersectSphere(moved, c + testing_support::gradingOffset(22), 1.5f, r.tmin, r.tmax, tRef);
    const auto trace = [&] { return testing_support::traceCase(moved, {}, c + testing_support::gradingOffset(22), 1.5f); };
    ASSERT_EQ(mine, ref) << (ref ? "a hit missed: " : "a miss hit: ") << trace();
    if (mine) {
      ++hits;
      ASSERT_NEAR(tMine, tRef, 1e-4f * std::max(1.0f, tRef)) << trace();
    }
  }
  EXPECT_GT(hits, 500);
}

// =============================================================================
// A2.3 Ray-triangle
// =============================================================================

class A2_3_RayTriangle : public testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(implemented("A2.3", [] {
      float t = 0.0f, b1 = 0.0f, b2 = 0.0f;
      (void)a2::rayTriangle(Ray{}, Vec3(0.0f), Vec3(1, 0, 0), Vec3(0, 1, 0), t, b1, b2);
    }));
  }
  const Vec3 p0{1.0f, -2.0f, 0.5f}, p1{3.0f, 1.0f, -1.0f}, p2{-1.0f, 2.0f, 2.0f};
};

TEST_F(A2_3_RayTriangle, KnownTAndBarycentrics) {
  float t = 0.0f, b1 = 0.0f, b2 = 0.0f;
  ASSERT_TRUE(a2::rayTriangle(makeRay({0.25f, 0.5f, 5.0f}, {0, 0, -1}), Vec3(0, 0, 0), Vec3(1, 0, 0),
                              Vec3(0, 1, 0), t, b1, b2));
  EXPECT_FLOAT_EQ(t, 5.0f);
  EXPECT_FLOAT_EQ(b1, 0.25f);
  EXPECT_FLOAT_EQ(b2, 0.5f);
  // General position: P = 0.2 p0 + 0.5 p1 + 0.3 p2, reached at t = 1.5 with |dir| = 2.
  const Vec3 P = 0.2f * p0 + 0.5f * p1 + 0.3f * p2;
  const Vec3 d = glm::normalize(Vec3(0.3f, -0.4f, 1.0f));
  ASSERT_TRUE(a2::rayTriangle(makeRay(P + 3.0f * d, -2.0f * d), p0, p1, p2, t, b1, b2));
  EXPECT_NEAR(t, 1.5f, 1e-5f);
  EXPECT_NEAR(b1, 0.5f, 1e-5f);
  EXPECT_NEAR(b2, 0.3f, 1e-5f);
}

TEST_F(A2_3_RayTriangle, BothFacesHit) {
  const Vec3 P = 0.6f * p0 + 0.1f * p1 + 0.3f * p2;
  const Vec3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  for (float side : {1.0f, -1.0f}) {
    float t = 0.0f, b1 = 0.0f, b2 = 0.0f;
    ASSERT_TRUE(a2::rayTriangle(makeRay(P + 2.0f * side * n, -side * n), p0, p1, p2, t, b1, b2)) << side;
    EXPECT_NEAR(t, 2.0f, 1e-5f);
    EXPECT_NEAR(b1, 0.1f, 1e-5f);
    EXPECT_NEAR(b2, 0.3f, 1e-5f);
  }
}

TEST_F(A2_3_RayTriangle, MissesOutsideEachEdgeAndWhenParallel) {
  const Vec3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  float t = 0.0f, b1 = 0.0f, b2 = 0.0f;
  // Just outside each edge: one barycentric slightly negative; just inside it, a hit (the control).
  for (Vec3 w : {Vec3(-0.02f, 0.5f, 0.52f), Vec3(0.5f, -0.02f, 0.52f), Vec3(0.5f, 0.52f, -0.02f)}) {
    const Vec3 P = w.x * p0 + w.y * p1 + w.z * p2;
    EXPECT_FALSE(a2::rayTriangle(makeRay(P + n, -n), p0, p1, p2, t, b1, b2)) << w.x << "," << w.y << "," << w.z;
    const Vec3 inside = 0.9f * P + 0.1f * (p0 + p1 + p2) / 3.0f;  // that barycentric now about +0.015
    EXPECT_TRUE(a2::rayTriangle(makeRay(inside + n, -n), p0, p1, p2, t, b1, b2)) << "just inside, near " << w.x << ","
                                                                                     << w.y << "," << w.z;
  }
  // Parallel to the triangle's plane.
  const Vec3 inPlane = p1 - p0;
  EXPECT_FALSE(a2::rayTriangle(makeRay(p0 + n - inPlane, inPlane), p0, p1, p2, t, b1, b2));
}

TEST_F(A2_3_RayTriangle, RespectsTminAndTmax) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  float t = 0.0f, b1 = 0.0f, b2 = 0.0f;
  const Vec3 o(0.2f, 0.2f, 5.0f), d(0, 0, -1);
  EXPECT_FALSE(a2::rayTriangle(makeRay(o, d, 0.0f, 4.9f), a, b, c, t, b1, b2));
  EXPECT_TRUE(a2::rayTriangle(makeRay(o, d, 0.0f, 5.1f), a, b, c, t, b1, b2));
  EXPECT_FALSE(a2::rayTriangle(makeRay(o, d, 5.1f), a, b, c, t, b1, b2));
  EXPECT_FALSE(a2::rayTriangle(makeRay({0.2f, 0.2f, -5.0f}, d), a, b, c, t, b1, b2));  // behind
}

TEST_F(A2_3_RayTriangle, RepeatedVertexNeverHits) {
  float t = 0.0f, b1 = 0.0f, b2 = 0.0f;
  const Vec3 a(0.1f, 0.2f, 0.3f), b(1.1f, 1.7f, 1.3f), c(0.9f, -0.4f, 0.8f);
  for (int i = 0; i <= 10; ++i) {
    const Vec3 target = a + (static_cast<float>(i) / 10.0f) * (b - a);
    const Vec3 o = target + Vec3(0.3f, -2.0f, 1.0f);
    EXPECT_FALSE(a2::rayTriangle(makeRay(o, target - o), a, a, b, t, b1, b2)) << i;
    EXPECT_FALSE(a2::rayTriangle(makeRay(o, target - o), a, b, b, t, b1, b2)) << i;
  }
  // The control: the same rays do hit a real triangle with that edge, between its ends.
  for (int i = 1; i < 10; ++i) {
    const Vec3 target = a + (static_cast<float>(i) / 10.0f) * (b - a) + 0.01f * (c - a);
    const Vec3 o = target + Vec3(0.3f, -2.0f, 1.0f);
    EXPECT_TRUE(a2::rayTriangle(makeRay(o, target - o), a, b, c, t, b1, b2)) << i;
  }
}

TEST_F(A2_3_RayTriangle, AgreesWithFrameworkAwayFromEdges) {
  std::mt19937 gen = testing_support::gradingRng(8);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  int hits = 0, checked = 0;
  for (int i = 0; i < 3000; ++i) {
    const Ray r = makeRay(Vec3(u(gen), u(gen), u(gen)), Vec3(u(gen), u(gen), u(gen)));
    float tRef = 0.0f, r1 = 0.0f, r2 = 0.0f;
    const bool ref = intersectTriangle(WatertightRay(r), p0, p1, p2, r.tmin, r.tmax, tRef, r1, r2);
    // Skip rays within 1e-3 of an edge (in barycentrics) of the plane hit.
    const DVec3 o(r.origin), d(r.dir), q0(p0), q1(p1), q2(p2);
    const DVec3 n = glm::cross(q1 - q0, q2 - q0);
    if (std::abs(glm::dot(n, d)) < 1e-9) continue;
    const DVec3 x = o + (glm::dot(n, q0 - o) / glm::dot(n, d)) * d;
    const double w1 = glm::dot(glm::cross(q2 - x, q0 - x), n) / glm::dot(n, n);
    const double w2 = glm::dot(glm::cross(q0 - x, q1 - x), n) / glm::dot(n, n);
    if (std::min(std::abs(w1), std::min(std::abs(w2), std::abs(1.0 - w1 - w2))) < 1e-3) continue;
    ++checked;
    float t = 0.0f, b1 = 0.0f, b2 = 0.0f;
    const bool mine = a2::rayTriangle(r, p0, p1, p2, t, b1, b2);
    const auto trace = [&] { return testing_support::traceCase(r, {p0, p1, p2}); };
    ASSERT_EQ(mine, ref) << (ref ? "a hit missed: " : "a miss hit: ") << trace();
    if (!mine) continue;
    ++hits;
    ASSERT_NEAR(t, tRef, 1e-4f * std::max(1.0f, tRef)) << trace();
    ASSERT_NEAR(b1, r1, 1e-4f) << trace();
    ASSERT_NEAR(b2, r2, 1e-4f) << trace();
  }
  EXPECT_GT(checked, 2800);
  EXPECT_GT(hits, 100);
}

// =============================================================================
// A2.4 Blinn-Phong
// =============================================================================

class A2_4_BlinnPhong : public testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(implemented("A2.4", [] {
      (void)a2::blinnPhong(a2::ShadingInput{Vec3(0, 0, 1), Vec3(0, 0, 1), Rgb(1.0f), Rgb(1.0f), 1.0f},
                           a2::LightInput{Vec3(0, 0, 1), 1.0f, Rgb(1.0f)});
    }));
  }
  static a2::ShadingInput surface(Vec3 n, Vec3 v, Rgb kd, Rgb ks, float p) { return {n, v, kd, ks, p}; }
  static a2::LightInput light(Vec3 l, float r, Rgb intensity) { return {l, r, intensity}; }
};

TEST_F(A2_4_BlinnPhong, HeadOnPointLight) {
  // n = l = v = h: both cosines 1. I / r^2 = (4, 8, 12) / 4 = (1, 2, 3).
  const Rgb L = a2::blinnPhong(surface({0, 0, 1}, {0, 0, 1}, {0.5f, 0.25f, 0.1f}, Rgb(0.2f), 10.0f),
                               light({0, 0, 1}, 2.0f, {4.0f, 8.0f, 12.0f}));
  // kd (1,2,3) + ks (1,2,3) = (0.5, 0.5, 0.3) + (0.2, 0.4, 0.6)
  expectVecNear(L, Rgb(0.7f, 0.9f, 0.9f), 1e-6f);
}

TEST_F(A2_4_BlinnPhong, SpecularPeakAtMirrorDirection) {
  // l and v mirrored about n: h = n, n.h = 1, n.l = 0.8.
  const Vec3 n(0, 0, 1), l(0.6f, 0, 0.8f), mirror(-0.6f, 0, 0.8f);
  const auto s = [&](Vec3 v) { return surface(n, v, Rgb(0.0f), Rgb(0.5f), 50.0f); };
  const Rgb peak = a2::blinnPhong(s(mirror), light(l, 1.0f, Rgb(2.0f)));
  expectVecNear(peak, Rgb(0.5f * 2.0f), 1e-6f);  // ks * I / r^2 * 1^p
  // Any other viewing direction sees less.
  for (float a : {-0.9f, -0.4f, -0.2f, 0.0f, 0.3f, 0.6f}) {
    const Vec3 v = glm::normalize(Vec3(a, 0.1f, 0.8f));
    EXPECT_LT(a2::blinnPhong(s(v), light(l, 1.0f, Rgb(2.0f))).r, peak.r) << a;
  }
  // And the exact value off the peak: v = (0,0,1): h = normalize(0.6, 0, 1.8), n.h = 3/sqrt(10).
  const double nh = 3.0 / std::sqrt(10.0);
  const Rgb off = a2::blinnPhong(s({0, 0, 1}), light(l, 1.0f, Rgb(2.0f)));
  EXPECT_NEAR(off.g, 0.5 * 2.0 * std::pow(nh, 50.0), 1e-6);
}

TEST_F(A2_4_BlinnPhong, DiffuseIsLambertCosine) {
  // ks = 0: kd I / r^2 n.l with n.l = 0.8, r = 2.5.
  const Rgb L = a2::blinnPhong(surface({0, 1, 0}, {0, 1, 0}, {0.3f, 0.6f, 0.9f}, Rgb(0.0f), 7.0f),
                               light({0.6f, 0.8f, 0.0f}, 2.5f, Rgb(5.0f)));
  const float e = 5.0f / 6.25f * 0.8f;
  expectVecNear(L, Rgb(0.3f, 0.6f, 0.9f) * e, 1e-6f);
}

TEST_F(A2_4_BlinnPhong, LightBelowTheSurfaceHasNoDiffuse) {
  // n.l = -0.8: the diffuse term is 0. The lecture's specular term is
  // max(0, n.h)^p on its own: h = normalize(v + l) = (0.6, 0, 0.2)/sqrt(0.4),
  // n.h^2 = 0.04 / 0.4 = 0.1, so with p = 2 it is ks * I * 0.1.
  const Rgb L = a2::blinnPhong(surface({0, 0, 1}, {0, 0, 1}, Rgb(0.9f), Rgb(0.5f), 2.0f),
                               light({0.6f, 0.0f, -0.8f}, 1.0f, Rgb(1.0f)));
  SCOPED_TRACE("light below the surface (n.l = -0.8): diffuse 0, but the specular term max(0, n.h)^p stays "
               "(ks I 0.1 = 0.05); A2.4 clamps each term on its own, unlike A1.4");
  expectVecNear(L, Rgb(0.05f), 1e-6f);
  // With the half vector also below the surface, nothing at all.
  const Rgb none = a2::blinnPhong(surface({0, 0, 1}, {0.8f, 0, 0.6f}, Rgb(0.9f), Rgb(0.5f), 2.0f),
                                  light({0.0f, 0.6f, -0.8f}, 1.0f, Rgb(1.0f)));
  EXPECT_EQ(none, Rgb(0.0f));
}

TEST_F(A2_4_BlinnPhong, InverseSquareFalloff) {
  const auto s = surface({0, 0, 1}, glm::normalize(Vec3(0.2f, 0.3f, 1.0f)), Rgb(0.4f), Rgb(0.3f), 12.0f);
  const Vec3 l = glm::normalize(Vec3(-0.5f, 0.1f, 1.0f));
  const Rgb near = a2::blinnPhong(s, light(l, 1.5f, Rgb(3.0f)));
  const Rgb far = a2::blinnPhong(s, light(l, 3.0f, Rgb(3.0f)));
  EXPECT_GT(near.r, 0.0f);
  EXPECT_NEAR(near.r / far.r, 4.0f, 1e-5f);
  // Doubling the intensity doubles the result.
  EXPECT_NEAR(a2::blinnPhong(s, light(l, 1.5f, Rgb(6.0f))).r, 2.0f * near.r, 1e-6f);
}

TEST_F(A2_4_BlinnPhong, DirectionalLightHasNoFalloff) {
  // distance = +infinity: E = I. l at 45 degrees: n.l = cos 45, and with
  // v = n, h is at 22.5 degrees: n.h = cos 22.5.
  const double pi = 3.14159265358979323846;
  const Rgb L = a2::blinnPhong(surface({0, 0, 1}, {0, 0, 1}, {0.8f, 0.4f, 0.2f}, {0.1f, 0.2f, 0.3f}, 8.0f),
                               light(glm::normalize(Vec3(0, 1, 1)), kInfinity, Rgb(0.5f)));
  const double diffuse = 0.5 * std::cos(pi / 4.0), specular = 0.5 * std::pow(std::cos(pi / 8.0), 8.0);
  const DVec3 expected = DVec3(0.8, 0.4, 0.2) * diffuse + DVec3(0.1, 0.2, 0.3) * specular;
  expectRgbRel(L, expected, 1e-5, "directional");
  EXPECT_TRUE(isFinite(L));
}

TEST_F(A2_4_BlinnPhong, ShininessSharpensTheHighlight) {
  const auto at = [&](float p) {
    return a2::blinnPhong(surface({0, 0, 1}, {0, 0, 1}, Rgb(0.0f), Rgb(1.0f), p),
                          light(glm::normalize(Vec3(0.5f, 0.0f, 1.0f)), 1.0f, Rgb(1.0f)))
        .r;
  };
  // n.h = cos(atan(0.5) / 2); exact powers.
  const double nh = std::cos(std::atan(0.5) / 2.0);
  EXPECT_NEAR(at(1.0f), nh, 1e-6);
  EXPECT_NEAR(at(100.0f), std::pow(nh, 100.0), 1e-6);
  EXPECT_LT(at(100.0f), at(10.0f));
}

// =============================================================================
// A2.5 Shadow rays
// =============================================================================

class A2_5_ShadowRay : public testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(implemented("A2.5", [] { (void)a2::shadowRay(point({0, 0, 0}, {0, 1, 0}), {0, 1, 0}, 1.0f); }));
  }
  static SurfacePoint point(Vec3 p, Vec3 n) {
    SurfacePoint sp;
    sp.position = p;
    sp.geometricNormal = n;
    sp.shadingNormal = n;
    return sp;
  }
  // Where the ray ends, in scene units from its origin.
  static float reach(const Ray& r) { return r.tmax * glm::length(r.dir); }
};

TEST_F(A2_5_ShadowRay, StartsOffTheSurfaceOnTheLightsSide) {
  // Floor point (1.5, 0, 0), light at (0, 3, 0) as in shadow_quad.json.
  const Vec3 p(1.5f, 0.0f, 0.0f), light(0.0f, 3.0f, 0.0f);
  const float distance = glm::length(light - p);
  const Vec3 l = (light - p) / distance;
  const Ray r = a2::shadowRay(point(p, {0, 1, 0}), l, distance);
  EXPECT_GT(r.origin.y + r.tmin * r.dir.y, 0.0f) << "the ray must start above the floor";
  EXPECT_LT(glm::length(r.origin - p), 1e-3f) << "but close to the point";
  EXPECT_NEAR(glm::dot(glm::normalize(r.dir), l), 1.0f, 1e-6f) << "towards the light";
  EXPECT_LT(reach(r), distance) << "ends before the light";
  EXPECT_GT(reach(r), 0.99f * distance) << "but not much before";
}

TEST_F(A2_5_ShadowRay, LightBehindTheNormalStartsOnTheOtherSide) {
  // The geometric normal points up, the light is below: leave downwards.
  const Vec3 p(0.25f, 2.0f, -0.5f);
  const Ray r = a2::shadowRay(point(p, {0, 1, 0}), {0, -1, 0}, 5.0f);
  EXPECT_LT(r.origin.y + r.tmin * r.dir.y, 2.0f);
  EXPECT_LT(glm::length(r.origin - p), 1e-3f);
  EXPECT_LT(r.dir.y, 0.0f);
}

TEST_F(A2_5_ShadowRay, DirectionalLightsReachInfinitely) {
  const Ray r = a2::shadowRay(point({1, 2, 3}, {0, 0, 1}), glm::normalize(Vec3(0, 1, 1)), kInfinity);
  EXPECT_GT(reach(r), 1e30f);
  float t = 0.0f;  // an occluder 1e5 away is still found
  EXPECT_TRUE(intersectSphere(r, Vec3(1.0f, 2.0f + 7e4f, 3.0f + 7e4f), 10.0f, r.tmin, r.tmax, t));
}

TEST_F(A2_5_ShadowRay, SeesOccludersBetweenButNotBeyond) {
  const Vec3 p(0.0f), lightPos(0.0f, 0.0f, 4.0f);
  const Ray r = a2::shadowRay(point(p, {0, 0, 1}), {0, 0, 1}, 4.0f);
  float t = 0.0f;
  EXPECT_TRUE(intersectSphere(r, Vec3(0, 0, 2), 0.5f, r.tmin, r.tmax, t));        // halfway
  EXPECT_TRUE(intersectSphere(r, Vec3(0, 0, 0.02f), 0.01f, r.tmin, r.tmax, t));   // very close
  EXPECT_TRUE(intersectSphere(r, Vec3(0, 0, 3.9f), 0.05f, r.tmin, r.tmax, t));    // just before the light
  EXPECT_FALSE(intersectSphere(r, Vec3(0, 0, 4.5f), 0.3f, r.tmin, r.tmax, t));    // behind the light
  // The light's own surface (an area light sample) must not block it.
  const WatertightRay w(r);
  float b1 = 0.0f, b2 = 0.0f;
  EXPECT_FALSE(intersectTriangle(w, lightPos + Vec3(-1, -1, 0), lightPos + Vec3(2, -1, 0), lightPos + Vec3(-1, 2, 0),
                                 r.tmin, r.tmax, t, b1, b2));
}

TEST_F(A2_5_ShadowRay, NoSelfShadowingFarFromTheOrigin) {
  // A big triangle with coordinates around 1e4 and a grazing light (about 2
  // degrees above the plane): no shadow ray from points on it may hit it.
  Geometry g;
  g.positions = {Vec3(1e4f, -3e3f, 2e4f), Vec3(1.3e4f, -2.9e3f, 2e4f), Vec3(1e4f, -2.8e3f, 2.3e4f)};
  g.triangles = {glm::uvec3(0, 1, 2)};
  g.triangleObject = {0};
  g.spheres = {Sphere{Vec3(-2e4f, 5e3f, 1e4f), 2e3f}};
  g.sphereObject = {1};
  const AcceleratorInfo& info = findAccelerator("none");
  const auto accel = buildAccelerator(info, ParamSet("accelerator 'none'", info.params), g);
  const Vec3 e1 = g.positions[1] - g.positions[0], e2 = g.positions[2] - g.positions[0];
  const Vec3 n = glm::normalize(glm::cross(e1, e2));
  const Frame frame(n);
  std::mt19937 gen = testing_support::gradingRng(12);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  QueryCounters counters;
  // The control: a shadow ray to a light behind the sphere is blocked (a ray that never hits
  // anything must not pass this test).
  const Vec3 sphereCentre = g.spheres[0].center, centroid = (g.positions[0] + g.positions[1] + g.positions[2]) / 3.0f;
  const Vec3 beyond = sphereCentre + (sphereCentre - centroid) * 0.5f;
  ASSERT_TRUE(accel->occluded(a2::shadowRay(point(centroid, n), glm::normalize(beyond - centroid),
                                            glm::length(beyond - centroid)),
                              counters))
      << "a shadow ray through the sphere";
  int tested = 0;
  for (int i = 0; i < 500; ++i) {
    float a = u(gen), b = u(gen);
    if (a + b > 1.0f) {
      a = 1.0f - a;
      b = 1.0f - b;
    }
    // Triangle point: light from 2 degrees above the plane, in a random azimuth.
    const Vec3 p = g.positions[0] + a * e1 + b * e2;
    const float phi = 6.2831853f * u(gen), elev = radians(2.0f);
    for (float side : {1.0f, -1.0f}) {
      const Vec3 l = frame.toWorld(Vec3(std::cos(elev) * std::cos(phi), std::cos(elev) * std::sin(phi),
                                        side * std::sin(elev)));
      ASSERT_FALSE(accel->occluded(a2::shadowRay(point(p, n), l, 50.0f), counters)) << i << " side " << side;
    }
    // Sphere point, light 2 degrees above its tangent plane.
    const Sphere& s = g.spheres[0];
    const Vec3 sn = glm::normalize(Vec3(u(gen) - 0.5f, u(gen) - 0.5f, u(gen) - 0.5f));
    const Vec3 sp = s.center + s.radius * sn;
    const Frame sf(sn);
    const Vec3 sl = sf.toWorld(Vec3(std::cos(elev) * std::cos(phi), std::cos(elev) * std::sin(phi), std::sin(elev)));
    ASSERT_FALSE(accel->occluded(a2::shadowRay(point(sp, sn), sl, 100.0f), counters)) << "sphere " << i;
    tested += 3;
  }
  EXPECT_EQ(tested, 1500);
}

// =============================================================================
// Whole renders: technique `raycast`, accelerator `none`, both intersection modes
// =============================================================================

struct Rendered {
  Image image;
  RenderStats stats;
  bool anyStub = false;
};

Rendered render(const Scene& scene, const std::string& intersection, RenderSettings settings,
                const std::vector<std::string>& assignments = {}) {
  const TechniqueInfo& tech = findTechnique("raycast");
  const AcceleratorInfo& accelInfo = findAccelerator("none");
  ParamSet params("technique 'raycast'", tech.params);
  params.set("intersection", intersection);
  for (const std::string& a : assignments) params.assign(a);
  const ParamSet accelParams("accelerator 'none'", accelInfo.params);
  const auto accel = buildAccelerator(accelInfo, accelParams, scene.geometry);
  const auto technique = tech.make();
  RenderJob job(scene, *accel, *technique, params, settings);
  job.run();
  return {job.frame().resolve(false), job.stats(), job.frame().anyStub()};
}

RenderSettings settingsOf(const Scene& s, int spp = 1) {
  RenderSettings r;
  r.width = s.camera.width;
  r.height = s.camera.height;
  r.spp = spp;
  return r;
}

// The primary ray through the continuous image position (px, py), in double,
// from the camera definition (independent of the code under test).
struct DRay {
  DVec3 o, d;
};
DRay cameraRayD(const Camera& c, int width, int height, double px, double py) {
  const DVec3 w = glm::normalize(DVec3(c.target) - DVec3(c.eye));
  const DVec3 u = glm::normalize(glm::cross(w, DVec3(c.up)));
  const DVec3 v = glm::cross(u, w);
  const double t = std::tan(static_cast<double>(c.fovYDeg) * 3.14159265358979323846 / 360.0);
  const double sx = (2.0 * px / width - 1.0) * t * width / height;
  const double sy = (1.0 - 2.0 * py / height) * t;
  return {DVec3(c.eye), glm::normalize(w + sx * u + sy * v)};
}

// Sphere hit in double; `margin` is |distance of the centre from the ray - r| / r.
bool sphereHitD(const DRay& r, const DVec3& c, double radius, double& t, double& margin) {
  const double tc = glm::dot(c - r.o, r.d);
  const double dist = glm::length(r.o + tc * r.d - c);
  margin = std::abs(dist - radius) / radius;
  if (dist >= radius) return false;
  t = tc - std::sqrt(radius * radius - dist * dist);
  return t > 0.0;
}

// The lecture's model for one point light, in double.
DVec3 blinnPhongD(const DVec3& n, const DVec3& v, const DVec3& p, const DVec3& lightPos, const DVec3& intensity,
                  const DVec3& kd, const DVec3& ks, double shininess) {
  const DVec3 toLight = lightPos - p;
  const double r = glm::length(toLight);
  const DVec3 l = toLight / r;
  if (glm::dot(n, l) <= 0.0) return DVec3(0.0);
  const DVec3 h = glm::normalize(v + l);
  const DVec3 e = intensity / (r * r);
  return kd * e * glm::dot(n, l) + ks * e * std::pow(std::max(0.0, glm::dot(n, h)), shininess);
}

const Material& materialNamed(const Scene& scene, const std::string& name) {
  for (const Material& m : scene.materials)
    if (m.name == name) return m;
  ADD_FAILURE() << "no material " << name;
  return scene.materials.front();
}

class A2_RaycastScene : public testing::TestWithParam<const char*> {
 protected:
  std::string mode() const { return GetParam(); }
  Rendered renderChecked(const Scene& scene, RenderSettings settings, const std::vector<std::string>& extra = {}) {
    Rendered r = render(scene, mode(), settings, extra);
    EXPECT_TRUE(r.stats.missingTasks.empty()) << missingTasks(r.stats);
    EXPECT_FALSE(r.anyStub);
    EXPECT_EQ(r.stats.work.nonFinite, 0u);
    EXPECT_EQ(r.stats.passes, settings.spp);
    EXPECT_FALSE(r.stats.cancelled);
    return r;
  }
};
// One suite per task the renders grade (the suite's name says which).
class A2_3_Scene : public A2_RaycastScene {};
class A2_4_Scene : public A2_RaycastScene {};
class A2_5_Scene : public A2_RaycastScene {};
class A2_Scene : public A2_RaycastScene {};

TEST_P(A2_4_Scene, SpherePointLightCentreIsAnalytic) {
  Scene scene = loadScene(kTestScenes + "sphere_point_light.json");
  // 65 x 65: the centre pixel's ray is the optical axis, n = l = v = h = (0,0,1), r = 4.
  RenderSettings s = settingsOf(scene);
  s.width = s.height = 65;
  const Rendered r = renderChecked(scene, s);
  ASSERT_TRUE(r.stats.missingTasks.empty());
  const Material& m = scene.materials[0];
  const Light& light = scene.lights[0];
  const double rr = 4.0 * 4.0;
  const DVec3 expected = DVec3(m.ka) * DVec3(scene.ambient) + DVec3(m.kd) * DVec3(light.intensity) / rr +
                         DVec3(m.ks) * DVec3(light.intensity) / rr;
  EXPECT_NEAR(expected.r, 0.645, 1e-6);  // the scene's description
  expectRgbRel(r.image.at(32, 32), expected, 1e-4, "centre pixel");
}

TEST_P(A2_4_Scene, SpherePointLightEveryPixelMatchesBlinnPhong) {
  const Scene scene = loadScene(kTestScenes + "sphere_point_light.json");
  const RenderSettings s = settingsOf(scene);
  const Rendered r = renderChecked(scene, s);
  ASSERT_TRUE(r.stats.missingTasks.empty());
  const Material& m = scene.materials[0];
  const DVec3 lightPos(scene.lights[0].position), I(scene.lights[0].intensity);
  const DVec3 ambient = DVec3(m.ka) * DVec3(scene.ambient);
  int sphere = 0, background = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const DRay ray = cameraRayD(scene.camera, s.width, s.height, x + 0.5, y + 0.5);
      double t = 0.0, margin = 0.0;
      const bool hit = sphereHitD(ray, DVec3(0.0), 1.0, t, margin);
      if (margin < 1e-3) continue;  // silhouette pixels: either answer is fine
      const std::string where = "pixel " + std::to_string(x) + "," + std::to_string(y) + " (trace it: " +
                                testing_support::traceCommand(scene.path, x, y, s.width, s.height) + ")";
      if (!hit) {
        ++background;
        EXPECT_EQ(r.image.at(x, y), Rgb(0.0f)) << where;
        continue;
      }
      ++sphere;
      const DVec3 p = ray.o + t * ray.d;
      const DVec3 value = ambient + blinnPhongD(glm::normalize(p), -ray.d, p, lightPos, I, DVec3(m.kd), DVec3(m.ks),
                                                static_cast<double>(m.shininess));
      expectRgbRel(r.image.at(x, y), value, 1e-4, where);
    }
  EXPECT_GT(sphere, 1000);
  EXPECT_GT(background, 1000);
}

TEST_P(A2_5_Scene, ShadowQuadShadowIsAmbientOnly) {
  const Scene scene = loadScene(kTestScenes + "shadow_quad.json");
  const RenderSettings s = settingsOf(scene);
  const Rendered r = renderChecked(scene, s);
  ASSERT_TRUE(r.stats.missingTasks.empty());
  const Material& floor = materialNamed(scene, "floor");
  const Material& ball = materialNamed(scene, "ball");
  const DVec3 lightPos(scene.lights[0].position), I(scene.lights[0].intensity), Ia(scene.ambient);
  const DVec3 centre(0.0, 0.8, 0.0);
  const double radius = 0.3;
  const DVec3 floorAmbient = DVec3(floor.ka) * Ia;  // 0.8 * 0.05 = 0.04
  EXPECT_NEAR(floorAmbient.r, 0.04, 1e-7);
  int shadowed = 0, lit = 0, onBall = 0;
  float brightestShadow = 0.0f, darkestLit = kInfinity;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const std::string where = "pixel " + std::to_string(x) + "," + std::to_string(y) + " (trace it: " +
                                testing_support::traceCommand(scene.path, x, y, s.width, s.height) + ")";
      const DRay ray = cameraRayD(scene.camera, s.width, s.height, x + 0.5, y + 0.5);
      double tBall = 0.0, margin = 0.0;
      const bool hitBall = sphereHitD(ray, centre, radius, tBall, margin);
      if (margin < 1e-3) continue;
      if (hitBall) {
        const DVec3 p = ray.o + tBall * ray.d;
        const DVec3 n = (p - centre) / radius;
        if (std::abs(glm::dot(n, glm::normalize(lightPos - p))) < 1e-3) continue;  // terminator
        ++onBall;
        const DVec3 value = DVec3(ball.ka) * Ia + blinnPhongD(n, -ray.d, p, lightPos, I, DVec3(ball.kd),
                                                              DVec3(ball.ks), static_cast<double>(ball.shininess));
        expectRgbRel(r.image.at(x, y), value, 1e-4, where + " (ball)");
        continue;
      }
      if (ray.d.y >= 0.0) continue;
      const DVec3 p = ray.o + (-ray.o.y / ray.d.y) * ray.d;
      if (std::max(std::abs(p.x), std::abs(p.z)) > 2.0 - 1e-3) {
        if (std::max(std::abs(p.x), std::abs(p.z)) > 2.0 + 1e-3) {
          EXPECT_EQ(r.image.at(x, y), Rgb(0.0f)) << where;
        }
        continue;
      }
      // Is the light blocked? Distance of the ball's centre from the segment p -> light.
      const DVec3 seg = lightPos - p;
      const double s01 = glm::dot(centre - p, seg) / glm::dot(seg, seg);
      const double dist = glm::length(p + s01 * seg - centre);
      if (std::abs(dist - radius) < 1e-3) continue;  // penumbra-free, but do not demand a side at the edge
      if (dist < radius) {
        ++shadowed;
        expectRgbRel(r.image.at(x, y), floorAmbient, 1e-4, where + " (shadow)");
        brightestShadow = std::max(brightestShadow, r.image.at(x, y).r);
      } else {
        ++lit;
        const DVec3 value = floorAmbient + blinnPhongD(DVec3(0, 1, 0), -ray.d, p, lightPos, I, DVec3(floor.kd),
                                                       DVec3(floor.ks), static_cast<double>(floor.shininess));
        expectRgbRel(r.image.at(x, y), value, 1e-4, where + " (lit floor)");
        darkestLit = std::min(darkestLit, r.image.at(x, y).r);
      }
    }
  EXPECT_GT(shadowed, 20);
  EXPECT_GT(lit, 1000);
  EXPECT_GT(onBall, 50);
  EXPECT_GT(darkestLit, brightestShadow) << "every lit floor pixel is brighter than the shadow";
}

TEST_P(A2_3_Scene, TriangleFanCoveredWithoutHoles) {
  const Scene scene = loadScene(kTestScenes + "triangle_fan.json");
  // 65 x 65: the middle column and row are rays exactly through the fan's
  // shared edges along the axes, the middle pixel exactly through the shared
  // centre vertex; the diagonals pass within float rounding of the others.
  RenderSettings s = settingsOf(scene);
  s.width = s.height = 65;
  const Rendered r = renderChecked(scene, s);
  ASSERT_TRUE(r.stats.missingTasks.empty());
  const Rgb kd = scene.materials[0].kd;
  EXPECT_EQ(kd, Rgb(0.8f, 0.6f, 0.2f));
  const std::vector<Vec3>& rim = scene.geometry.positions;
  int inside = 0, covered = 0, outside = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const DRay ray = cameraRayD(scene.camera, s.width, s.height, x + 0.5, y + 0.5);
      const DVec3 p = ray.o + (-ray.o.z / ray.d.z) * ray.d;
      // Signed distance inside the octagon (min over its 8 outer edges).
      double d = 1e9;
      for (size_t k = 1; k <= 8; ++k) {
        const DVec3 a(rim[k]), b(rim[k == 8 ? 1 : k + 1]);
        const DVec3 e = glm::normalize(b - a);
        d = std::min(d, e.x * (p.y - a.y) - e.y * (p.x - a.x));  // left of a counter-clockwise edge
      }
      const Rgb& c = r.image.at(x, y);
      const std::string where = "pixel " + std::to_string(x) + "," + std::to_string(y) + " (trace it: " +
                                testing_support::traceCommand(scene.path, x, y, s.width, s.height) + ")";
      if (d > 1e-3) {
        ++inside;
        if (c == kd) ++covered;
        EXPECT_NEAR(c.r, kd.r, 1e-6f) << where << " is a hole";
        EXPECT_NEAR(c.g, kd.g, 1e-6f) << where;
        EXPECT_NEAR(c.b, kd.b, 1e-6f) << where;
      } else if (d < -1e-3) {
        ++outside;
        EXPECT_EQ(c, Rgb(0.0f)) << where;
      }
    }
  EXPECT_GT(inside, 1500);
  EXPECT_GT(outside, 1000);
  EXPECT_EQ(covered, inside);
  EXPECT_EQ(r.image.at(32, 32), kd) << "ray through the shared centre vertex";
  for (int i = 10; i < 55; ++i) {
    EXPECT_EQ(r.image.at(32, i), kd) << "shared edge x = 0, row " << i;
    EXPECT_EQ(r.image.at(i, 32), kd) << "shared edge y = 0, column " << i;
  }
}

TEST_P(A2_Scene, SameImageForAnyThreadCountAndTileOrder) {
  // The Cornell box with jittered samples (spp 2) and area-light sampling uses
  // the per-pixel random streams: the image must not depend on which thread
  // renders which tile or in which order (1 thread: tiles in order; 2 and 8
  // threads: work-stealing order).
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/cornell_box.json");
  RenderSettings s;
  s.width = 40;
  s.height = 24;
  s.spp = 2;
  s.seed = 99;
  const std::vector<std::string> extra = {"light_samples=4"};
  Rendered one, two, eight;
  {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = renderChecked(scene, s, extra);
  }
  {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    two = renderChecked(scene, s, extra);
  }
  {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 8);
    tbb::task_arena arena(8);
    arena.execute([&] { eight = renderChecked(scene, s, extra); });
  }
  ASSERT_EQ(one.image.pixelCount(), 40u * 24u);
  EXPECT_TRUE(one.image.pixels() == two.image.pixels()) << "1 vs 2 threads";
  EXPECT_TRUE(one.image.pixels() == eight.image.pixels()) << "1 vs 8 threads";
  EXPECT_EQ(one.stats.work.rays, two.stats.work.rays);
  EXPECT_EQ(one.stats.work.rays, eight.stats.work.rays);
  for (const Rgb& p : one.image.pixels()) ASSERT_TRUE(isFinite(p));
  // ...while another seed gives another image (the seed is used).
  s.seed = 100;
  const Rendered other = renderChecked(scene, s, extra);
  EXPECT_FALSE(one.image.pixels() == other.image.pixels());
}

TEST_P(A2_Scene, RayCountsMatchTheScene) {
  // One sphere and one point light: the effects say nothing can cast a
  // shadow, so the technique casts no shadow ray at all.
  const Scene sphere = loadScene(kTestScenes + "sphere_point_light.json");
  ASSERT_FALSE(sphere.effects.has(Effect::HardShadows));
  RenderSettings s;
  s.width = 24;
  s.height = 16;
  s.spp = 3;
  const Rendered r = renderChecked(sphere, s);
  const auto& rays = r.stats.work.rays;
  EXPECT_EQ(rays[static_cast<size_t>(RayKind::Camera)], 24u * 16u * 3u);
  EXPECT_EQ(rays[static_cast<size_t>(RayKind::Shadow)], 0u);
  EXPECT_EQ(rays[static_cast<size_t>(RayKind::Reflection)], 0u);
  EXPECT_EQ(rays[static_cast<size_t>(RayKind::Refraction)], 0u);
  EXPECT_EQ(rays[static_cast<size_t>(RayKind::Indirect)], 0u);
  EXPECT_EQ(r.stats.work.query.primitivesTested, 24u * 16u * 3u) << "brute force over one primitive";
  EXPECT_EQ(r.stats.width, 24);
  EXPECT_EQ(r.stats.spp, 3);

  // A sphere over a floor: shadow rays, at most one per camera ray (one light).
  const Scene quad = loadScene(kTestScenes + "shadow_quad.json");
  ASSERT_TRUE(quad.effects.has(Effect::HardShadows));
  const Rendered q = renderChecked(quad, s);
  const uint64_t camera = q.stats.work.rays[static_cast<size_t>(RayKind::Camera)];
  const uint64_t shadow = q.stats.work.rays[static_cast<size_t>(RayKind::Shadow)];
  EXPECT_EQ(camera, 24u * 16u * 3u);
  EXPECT_GT(shadow, camera / 4);
  EXPECT_LE(shadow, camera);
  EXPECT_EQ(q.stats.work.totalRays(), camera + shadow);
}

// intersection=auto (the default): your tests over every primitive with -a none, the chosen
// accelerator's otherwise (an accelerator picked in the GUI or with -a is never silently ignored).
TEST(A2_Raycast, AutoIntersectionUsesTheChosenAccelerator) {
  using testing_support::renderSettings, testing_support::renderWith;
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/bunny.json");
  const RenderSettings s = renderSettings(16, 16);
  const uint64_t prims = scene.geometry.primitiveCount();
  const auto run = [&](const std::string& accel, const std::string& mode) {
    return renderWith(scene, "raycast", accel, {{"intersection", mode}}, s).stats.work;
  };
  const WorkCounters none = run("none", "auto"), bvh = run("bvh", "auto"), forced = run("bvh", "student");
  const auto camera = [](const WorkCounters& w) { return w.rays[static_cast<size_t>(RayKind::Camera)]; };
  // Brute force tests every primitive for each camera ray (shadow rays may stop at the first hit).
  EXPECT_GE(none.query.primitivesTested, prims * camera(none)) << "-a none: brute force";
  EXPECT_EQ(none.query.nodesVisited, 0u);
  EXPECT_GT(bvh.query.nodesVisited, 0u) << "-a bvh: the BVH answers the queries";
  EXPECT_LT(bvh.query.primitivesTested, prims * camera(bvh) / 10);
  EXPECT_GE(forced.query.primitivesTested, prims * camera(forced)) << "student: brute force with any -a";
  EXPECT_EQ(forced.query.nodesVisited, 0u);
}

// Test names: A2/A2_4_Scene.<Test>/framework and .../student (the intersection mode of
// `raycast`). The suite names the task a test grades; every other task runs its reference.
const auto paramName = [](const testing::TestParamInfo<const char*>& p) { return std::string(p.param); };
INSTANTIATE_TEST_SUITE_P(A2, A2_4_Scene, testing::Values("framework", "student"), paramName);
INSTANTIATE_TEST_SUITE_P(A2, A2_5_Scene, testing::Values("framework", "student"), paramName);
INSTANTIATE_TEST_SUITE_P(A2, A2_Scene, testing::Values("framework", "student"), paramName);
// Only your intersection tests exercise A2.3 (intersection=framework uses the accelerator's).
INSTANTIATE_TEST_SUITE_P(A2, A2_3_Scene, testing::Values("student"), paramName);

}  // namespace
}  // namespace ll
