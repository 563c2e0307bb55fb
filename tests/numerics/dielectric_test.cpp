// Whole renders of glass at grazing angles with no NaN or Inf, near and far
// from the origin. (The dielectric functions' own hard cases -- the critical
// angle float by float, grazing and normal incidence, equal indices -- are
// graded with their tasks: assignments/a3_whitted/a3_hard_cases_test.cpp.)
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "a3_tasks.h"
#include "modules/registry.h"
#include "render/render_job.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

// The student tree's stubs (LIGHTLAB_SOLUTION=0) are graded by its own task tests, not held to these.
#define SKIP_WITHOUT_SOLUTION() \
  if (!LIGHTLAB_SOLUTION) GTEST_SKIP() << "checks the solution of A3.2/A3.3"

// A glass ball (and a glass ball inside a water ball) filling the view: the silhouette pixels hit at grazing angles.
TEST(Numerics_Dielectric, GlassAtGrazingAnglesRendersWithoutNaNOrInfNearAndFarFromTheOrigin) {
  SKIP_WITHOUT_SOLUTION();
  for (const Vec3 o : {Vec3(0.0f), Vec3(1e5f, -1e5f, 1e5f)}) {
    const auto at = [&](float x, float y, float z) {
      return "[" + std::to_string(o.x + x) + ", " + std::to_string(o.y + y) + ", " + std::to_string(o.z + z) + "]";
    };
    const std::string offset = at(0, 0, 0);
    const Scene moved = parseJsonScene(R"({
      "camera": {"eye": )" + at(0, 0, 3) + R"(, "target": )" + offset + R"(, "up": [0, 1, 0], "fov_y_deg": 40, "width": 48, "height": 48},
      "background": [0.2, 0.4, 0.9],
      "materials": {"glass": {"transmission": [1, 1, 1], "ior": 1.5}, "water": {"transmission": [0.9, 0.95, 1], "ior": 1.33},
                    "floor": {"kd": [0.8, 0.8, 0.8]}},
      "lights": [{"type": "point", "position": )" + at(2, 3, 3) + R"(, "intensity": [10, 10, 10]}],
      "objects": [
        {"type": "sphere", "material": "water", "center": )" + offset + R"(, "radius": 1},
        {"type": "sphere", "material": "glass", "center": )" + offset + R"(, "radius": 0.5},
        {"type": "quad", "material": "floor", "vertices": [)" + at(-5, -1, 5) + ", " + at(5, -1, 5) + ", " +
                                       at(5, -1, -5) + ", " + at(-5, -1, -5) + R"(]}
      ]})",
                                       "grazing_glass.json", ".");
    const AcceleratorInfo& a = findAccelerator("bvh");
    const auto accel = buildAccelerator(a, ParamSet(a.name, a.params), moved.geometry);
    const TechniqueInfo& info = findTechnique("whitted");
    const ParamSet params(info.name, info.params);
    RenderSettings settings;
    settings.width = settings.height = 48;
    settings.spp = 4;
    const auto technique = info.make();
    RenderJob job(moved, *accel, *technique, params, settings);
    job.run();
    EXPECT_EQ(job.stats().work.nonFinite, 0u) << offset;
    EXPECT_GT(job.stats().work.rays[static_cast<size_t>(RayKind::Refraction)], 48u * 48u) << offset;
    const Image image = job.frame().resolve(false);
    for (const Rgb& c : image.pixels()) ASSERT_TRUE(isFinite(c)) << offset;
  }
}

}  // namespace
}  // namespace ll
