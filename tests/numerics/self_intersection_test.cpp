// Hard cases: secondary rays leaving curved and tilted surfaces, near the
// origin and 1e5 away from it, with objects of unit size. Shadow and
// reflection rays that leave a convex surface never hit it again; refraction
// rays that enter it find its far side (a glass sphere of radius 0.5 is
// crossed along its chord, a glass slab 0.5 thick is crossed to its far
// face), for every accelerator. The origins come from render/ray_offset.h,
// which every technique uses.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "numerics/numerics_support.h"
#include "render/ray_offset.h"
#include "scene/scene_loader.h"

namespace ll::numerics {
namespace {

std::string num(float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(v));
  return buf;
}

// A sphere of radius 0.5 at `c`, and a slab 0.5 thick tilted about x, 3 units away: both of unit size.
Scene smallObjectsAt(Vec3 c) {
  const std::string t = "[" + num(c.x) + ", " + num(c.y) + ", " + num(c.z) + "]";
  return parseJsonScene(R"({
    "camera": {"eye": [0, 0, 10], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 40, "width": 8, "height": 8},
    "materials": {"glass": {"transmission": [1, 1, 1], "ior": 1.5}},
    "objects": [
      {"type": "sphere", "name": "ball", "material": "glass", "center": [0, 0, 0], "radius": 0.5, "transform": {"translate": )" + t + R"(}},
      {"type": "quad", "name": "top", "material": "glass", "transform": {"rotate_deg": [35, 20, 0], "translate": )" + t + R"(},
       "vertices": [[2, -1, 0.25], [4, -1, 0.25], [4, 1, 0.25], [2, 1, 0.25]]},
      {"type": "quad", "name": "bottom", "material": "glass", "transform": {"rotate_deg": [35, 20, 0], "translate": )" + t + R"(},
       "vertices": [[2, -1, -0.25], [2, 1, -0.25], [4, 1, -0.25], [4, -1, -0.25]]}
    ]})",
                        "small_objects.json", ".");
}

// The far root of |o + t d - c| = r in double (d unit): where a ray from inside leaves the sphere.
float farRoot(const Ray& r, Vec3 c, double radius) {
  const glm::dvec3 f = glm::dvec3(r.origin) - glm::dvec3(c), d(r.dir);
  const double b = glm::dot(f, d), q = glm::dot(f, f) - radius * radius;
  return static_cast<float>(-b + std::sqrt(b * b - q));
}

// Scales: near the origin, 1e3 and 1e5 away (where one float ulp is 0.0078).
const float kOffsets[] = {0.0f, 1e3f, 1e5f};

TEST(Numerics_SelfIntersection, RaysLeavingOrEnteringASmallSphereFarFromTheOrigin) {
  for (float s : kOffsets) {
    const Vec3 c = s * Vec3(1.0f, 0.7f, -0.4f);
    const Scene scene = smallObjectsAt(c);
    const uint32_t ball = scene.geometry.triangleCount();  // spheres come after the triangles
    const float ulp = std::max(1e-6f, std::nextafter(s * 1.1f, kInfinity) - s * 1.1f);
    for (const BuiltAccelerator& a : everyAccelerator(scene.geometry)) {
      SCOPED_TRACE(a.name + " at " + num(s));
      QueryCounters counters;
      int points = 0;
      for (int i = -3; i <= 3; ++i)
        for (int j = -3; j <= 3; ++j) {
          const Vec3 eye = c + Vec3(0.0f, 0.0f, 6.0f);
          const Vec3 aim = c + Vec3(0.1f * static_cast<float>(i), 0.1f * static_cast<float>(j), 0.0f);
          const Ray camera = ray(eye, aim - eye);
          Hit hit;
          ASSERT_TRUE(a.accel->intersect(camera, hit, counters));
          ASSERT_EQ(hit.prim, ball);
          const SurfacePoint sp = scene.surfacePoint(camera, hit);
          const Vec3 n = sp.geometricNormal;
          ++points;
          // Leaving: a shadow ray to a light outside, a mirror reflection. Nothing else is in the way.
          const Vec3 toLight = glm::normalize(Vec3(-0.3f, 0.2f, 1.0f));
          const Vec3 reflected = glm::reflect(glm::normalize(camera.dir), n);
          for (const Vec3& d : {toLight, reflected}) {
            if (glm::dot(d, n) <= 0.05f) continue;  // below the horizon: it would enter the ball
            Hit again;
            EXPECT_FALSE(a.accel->intersect(ray(offsetRayOrigin(sp.position, faceTowards(n, d)), d), again, counters))
                << "self-hit at t = " << again.t << " from point " << i << "," << j;
          }
          // Entering along -n and obliquely: the far side, where the double-precision quadratic puts it.
          for (const Vec3& d : {-n, glm::normalize(-n + 0.4f * glm::normalize(glm::cross(n, Vec3(0.3f, 0.2f, 1.0f))))}) {
            const Ray in = ray(offsetRayOrigin(sp.position, faceTowards(n, d)), d);
            EXPECT_LE(glm::length(in.origin - sp.position), 16.0f * ulp + 1e-4f) << "the origin moved too far";
            Hit exit;
            ASSERT_TRUE(a.accel->intersect(in, exit, counters)) << "the refraction ray missed the ball's far side";
            EXPECT_EQ(exit.prim, ball);
            EXPECT_NEAR(exit.t, farRoot(in, c, 0.5), 8.0f * ulp + 1e-5f) << "point " << i << "," << j;
          }
        }
      EXPECT_EQ(points, 49);
    }
  }
}

// A wall in a coordinate plane, 550 units across (the Cornell box's right wall, x = 0, and its
// floor, y = 0): its points have one exact zero coordinate, but a ray leaving one is tested against
// the wall in coordinates of size 500. Shadow rays to the point light below the ceiling never hit
// their own wall. (An offset by the ulps of each coordinate moved x by 2^-16 only, and a third of
// the right wall's lower half was in its own shadow: speckled acne on the shadow-ray slide.)
TEST(Numerics_SelfIntersection, ShadowRaysFromALargeWallInACoordinatePlane) {
  const Scene scene = parseJsonScene(R"({
    "camera": {"eye": [278, 273, -800], "target": [278, 273, 0], "up": [0, 1, 0], "fov_y_deg": 39.3, "width": 8, "height": 8},
    "materials": {"white": {"kd": [0.7, 0.7, 0.7]}},
    "objects": [
      {"type": "quad", "name": "right_wall", "material": "white", "vertices": [[0, 0, 559.2], [0, 0, 0], [0, 548.8, 0], [0, 548.8, 559.2]]},
      {"type": "quad", "name": "floor", "material": "white", "vertices": [[552.8, 0, 0], [0, 0, 0], [0, 0, 559.2], [549.6, 0, 559.2]]}
    ]})",
                                     "walls.json", ".");
  const Vec3 light(278.0f, 545.0f, 279.5f), eye(278.0f, 273.0f, -800.0f);
  for (const BuiltAccelerator& a : everyAccelerator(scene.geometry)) {
    SCOPED_TRACE(a.name);
    QueryCounters counters;
    int points = 0, blocked = 0;
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 40; ++j) {
        // Points on the right wall and on the floor, seen from the camera.
        const Vec3 aim = i % 2 == 0 ? Vec3(0.0f, 5.0f + 13.5f * static_cast<float>(j), 20.0f + 13.0f * static_cast<float>(i))
                                    : Vec3(20.0f + 12.9f * static_cast<float>(j), 0.0f, 20.0f + 13.0f * static_cast<float>(i));
        const Ray camera = ray(eye, aim - eye);
        Hit hit;
        if (!a.accel->intersect(camera, hit, counters)) continue;
        const SurfacePoint sp = scene.surfacePoint(camera, hit);
        const Vec3 toLight = light - sp.position;
        const float distance = glm::length(toLight);
        Ray shadow = ray(offsetRayOrigin(sp.position, faceTowards(sp.geometricNormal, toLight)), toLight / distance);
        shadow.tmax = distance * (1.0f - 1e-4f);
        ++points;
        Hit again;
        if (a.accel->intersect(shadow, again, counters) && ++blocked <= 3)
          ADD_FAILURE() << "the shadow ray from " << sp.position.x << ", " << sp.position.y << ", " << sp.position.z
                        << " hit its own wall (primitive " << again.prim << ") at t = " << again.t;
      }
    EXPECT_GT(points, 1000);
    EXPECT_EQ(blocked, 0) << "of " << points << " shadow rays";
  }
}

TEST(Numerics_SelfIntersection, RaysLeavingOrEnteringATiltedSlabFarFromTheOrigin) {
  for (float s : kOffsets) {
    const Vec3 c = s * Vec3(1.0f, 0.7f, -0.4f);
    const Scene scene = smallObjectsAt(c);
    const float ulp = std::max(1e-6f, std::nextafter(s * 1.1f, kInfinity) - s * 1.1f);
    const uint32_t topFirst = scene.objects[1].firstPrim, bottomFirst = scene.objects[2].firstPrim;
    for (const BuiltAccelerator& a : everyAccelerator(scene.geometry)) {
      SCOPED_TRACE(a.name + " at " + num(s));
      QueryCounters counters;
      // The top face's centre and outward normal, from its two triangles.
      const glm::uvec3 t0 = scene.geometry.triangles[topFirst];
      const Vec3 q0 = scene.geometry.positions[t0.x], q1 = scene.geometry.positions[t0.y],
                 q2 = scene.geometry.positions[t0.z];
      const Vec3 n = glm::normalize(glm::cross(q1 - q0, q2 - q0));
      int points = 0;
      for (float u : {0.2f, 0.35f, 0.5f, 0.65f, 0.8f})
        for (float v : {0.2f, 0.5f, 0.8f}) {
          const Vec3 target = q0 + u * (q1 - q0) + v * (q2 - q1);  // inside the top quad's first triangle for v < u
          if (v >= u) continue;
          const Vec3 eye = target + 5.0f * glm::normalize(n + Vec3(0.1f, -0.2f, 0.0f));
          const Ray camera = ray(eye, target - eye);
          Hit hit;
          ASSERT_TRUE(a.accel->intersect(camera, hit, counters));
          ASSERT_TRUE(hit.prim == topFirst || hit.prim == topFirst + 1) << hit.prim;
          const SurfacePoint sp = scene.surfacePoint(camera, hit);
          ++points;
          // Leaving upwards (a shadow ray, the reflection): nothing.
          for (const Vec3& d : {n, glm::reflect(glm::normalize(camera.dir), n)}) {
            Hit again;
            EXPECT_FALSE(a.accel->intersect(ray(offsetRayOrigin(sp.position, faceTowards(n, d)), d), again, counters))
                << "self-hit at t = " << again.t;
          }
          // Entering (a refraction ray, a shadow ray to a light below): the bottom face, 0.5 / cos away.
          for (const Vec3& d : {-n, glm::normalize(-n + Vec3(0.2f, 0.1f, 0.0f))}) {
            const Ray in = ray(offsetRayOrigin(sp.position, faceTowards(n, d)), d);
            EXPECT_LE(glm::length(in.origin - sp.position), 16.0f * ulp + 1e-4f) << "the origin moved too far";
            Hit below;
            ASSERT_TRUE(a.accel->intersect(in, below, counters)) << "the refraction ray missed the slab's far face";
            EXPECT_TRUE(below.prim == bottomFirst || below.prim == bottomFirst + 1) << below.prim;
            // The bottom plane is 0.5 below the top one: from the origin, (0.5 - its depth) / cos.
            const float depth = glm::dot(sp.position - in.origin, n);
            EXPECT_NEAR(below.t, (0.5f - depth) / glm::dot(-n, d), 8.0f * ulp + 1e-5f);
            EXPECT_TRUE(a.accel->occluded(ray(in.origin, d, 0.0f, 10.0f), counters));
          }
        }
      EXPECT_GE(points, 6);
    }
  }
}

}  // namespace
}  // namespace ll::numerics
