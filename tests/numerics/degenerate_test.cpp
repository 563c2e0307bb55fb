// Hard cases: degenerate triangles (a repeated vertex, exactly collinear
// vertices, a point) are never hit by any accelerator, so no hit ever asks for
// a normal that does not exist; sliver triangles (20000 times longer than wide)
// are hit exactly where they are, with a finite unit normal; the scene loader
// drops zero-area triangles and keeps slivers.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "numerics/numerics_support.h"
#include "scene/scene_loader.h"

namespace ll::numerics {
namespace {

TEST(Numerics_Degenerate, ZeroAreaTrianglesAreNeverHitAndDoNotHideWhatIsBehind) {
  Geometry g;
  const Vec3 a(0.125f, 0.25f, 0.375f), b(1.125f, 1.75f, 1.375f), c(2.125f, 3.25f, 2.375f);
  ASSERT_EQ(glm::cross(b - a, c - a), Vec3(0.0f));  // exactly collinear in float
  addTriangle(g, a, b, c);                           // 0: collinear
  addTriangle(g, b, c, a);                           // 1: the same, rotated
  addTriangle(g, a, a, c);                           // 2: a repeated vertex
  addTriangle(g, b, b, b);                           // 3: a point
  addQuad(g, Vec3(-5.0f, -5.0f, -4.0f), Vec3(20.0f, 0.0f, 0.0f), Vec3(0.0f, 20.0f, 0.0f));  // 4, 5: z = -4
  for (const BuiltAccelerator& acc : everyAccelerator(g)) {
    SCOPED_TRACE(acc.name);
    QueryCounters counters;
    int rays = 0;
    // Rays from above through points of the segment a-c (and its ends), down to the floor z = -4.
    for (int k = 0; k <= 64; ++k) {
      const Vec3 target = a + (static_cast<float>(k) / 64.0f) * (c - a);
      for (const Vec3& from : {Vec3(0.3f, -0.2f, 6.0f), Vec3(-2.0f, 3.0f, 5.0f), Vec3(4.0f, 1.0f, 7.0f)}) {
        const Ray r = ray(from, target - from);
        Hit hit;
        ++rays;
        ASSERT_TRUE(acc.accel->intersect(r, hit, counters));
        ASSERT_GE(hit.prim, 4u) << "degenerate triangle " << hit.prim << " hit through point " << k;
        // The floor at z = -4: t = (from.z + 4) / (from.z - target.z).
        EXPECT_NEAR(hit.t, (from.z + 4.0f) / (from.z - target.z), 1e-5f);
        // A shadow ray ending just short of the floor sees nothing.
        ASSERT_FALSE(acc.accel->occluded(ray(from, target - from, 0.0f, 0.999f * hit.t), counters)) << k;
      }
    }
    EXPECT_EQ(rays, 65 * 3);
  }
}

TEST(Numerics_Degenerate, SliverTrianglesAreHitExactlyWithAFiniteNormal) {
  // Slivers 2 long and 1e-4 wide (~500 float ulps of their coordinates), at several orientations.
  Geometry g;
  const float width = 1e-4f;
  std::vector<Vec3> from;
  for (int k = 0; k < 4; ++k) {
    const Vec3 o(0.75f * static_cast<float>(k), 0.0f, 0.0f);
    const Vec3 along = glm::normalize(Vec3(1.0f, 0.3f * static_cast<float>(k), 0.1f));
    const Vec3 across = glm::normalize(glm::cross(along, Vec3(0.2f, 0.1f, 1.0f)));
    addTriangle(g, o, o + 2.0f * along, o + along + width * across);
  }
  for (const BuiltAccelerator& acc : everyAccelerator(g)) {
    SCOPED_TRACE(acc.name);
    QueryCounters counters;
    for (uint32_t p = 0; p < g.triangleCount(); ++p) {
      const glm::uvec3 t = g.triangles[p];
      const Vec3 p0 = g.positions[t.x], p1 = g.positions[t.y], p2 = g.positions[t.z];
      const Vec3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
      ASSERT_TRUE(isFinite(n));
      for (float b2 : {0.25f, 0.5f, 0.75f}) {  // well inside: the sliver's middle, across its width
        const float b1 = 0.5f * (1.0f - b2);
        const Vec3 target = (1.0f - b1 - b2) * p0 + b1 * p1 + b2 * p2;
        const Ray r = ray(target + 2.0f * n, -n);
        Hit hit;
        ASSERT_TRUE(acc.accel->intersect(r, hit, counters)) << "sliver " << p << " at b2 = " << b2;
        EXPECT_EQ(hit.prim, p);
        EXPECT_NEAR(hit.t, 2.0f, acc.exactOnEdges() ? 1e-5f : 1e-4f);  // Embree's t loses more on a sliver
        if (acc.exactOnEdges()) {
          EXPECT_NEAR(hit.b1, b1, 0.01f);
          EXPECT_NEAR(hit.b2, b2, 0.01f);  // across the sliver: its width is ~500 ulps
        }
      }
      // Beside the sliver by one width, off its long edge: a miss.
      const Vec3 beside = 0.5f * (p0 + p1) - width * glm::normalize(glm::cross(n, p1 - p0));
      Hit hit;
      EXPECT_FALSE(acc.accel->intersect(ray(beside + 2.0f * n, -n), hit, counters)) << "sliver " << p;
    }
  }
}

TEST(Numerics_Degenerate, TheSceneLoaderDropsZeroAreaTrianglesAndKeepsSlivers) {
  const Scene scene = parseJsonScene(R"({
    "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 40, "width": 8, "height": 8},
    "materials": {"m": {"kd": [0.5, 0.5, 0.5]}},
    "lights": [{"type": "point", "position": [0, 0, 5], "intensity": [1, 1, 1]}],
    "objects": [
      {"type": "triangles", "material": "m", "positions": [[0, 0, 0], [1, 1, 1], [2, 2, 2], [1, 0, 0], [0.5, 0.000001, 0]],
       "indices": [[0, 1, 2], [0, 0, 3], [0, 3, 4]]}
    ]})",
                                     "slivers.json", ".");
  ASSERT_EQ(scene.geometry.triangleCount(), 1u);  // the collinear and the repeated-vertex ones are gone
  const Hit hit = [&] {
    Hit h;
    h.prim = 0;
    h.t = 5.0f;
    h.b1 = 0.25f;
    h.b2 = 0.5f;
    return h;
  }();
  const SurfacePoint sp = scene.surfacePoint(ray(Vec3(0.5f, 5e-7f, 5.0f), Vec3(0.0f, 0.0f, -1.0f)), hit);
  EXPECT_TRUE(isFinite(sp.geometricNormal));
  EXPECT_NEAR(std::abs(sp.geometricNormal.z), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::length(sp.shadingNormal), 1.0f, 1e-6f);
}

}  // namespace
}  // namespace ll::numerics
