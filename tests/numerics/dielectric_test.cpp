// Hard cases of assignment 3's dielectric code (the solution): refraction and
// Fresnel at the exact critical angle and float by float around it, at
// grazing incidence, at normal incidence, with cos(theta_i) rounded past 1,
// and with equal indices on both sides (nested dielectrics of one glass: no
// interface at all); and whole renders of glass at grazing angles with no
// NaN or Inf.
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

Vec3 incoming(float cosI) {  // unit, towards the surface z = 0 whose normal is +z
  return Vec3(std::sqrt(std::max(0.0f, 1.0f - cosI * cosI)), 0.0f, -cosI);
}

TEST(Numerics_Dielectric, AroundTheCriticalAngleFloatByFloatEitherRefractsOrReflectsTotally) {
  SKIP_WITHOUT_SOLUTION();
  const float n1 = 1.5f, n2 = 1.0f, eta = n1 / n2;
  const float cosCritical = std::sqrt(1.0f - 1.0f / (eta * eta));  // cos(41.81 deg)
  float cosI = cosCritical;
  for (int k = 0; k < 256; ++k) cosI = std::nextafter(cosI, 0.0f);
  int refracted = 0, total = 0;
  for (int k = 0; k < 512; ++k, cosI = std::nextafter(cosI, 1.0f)) {
    Vec3 t(7.0f);
    const bool ok = a3::refract(incoming(cosI), Vec3(0, 0, 1), eta, t);
    const a3::FresnelTerms f = a3::fresnelDielectric(cosI, n1, n2);
    ASSERT_TRUE(std::isfinite(f.rs) && std::isfinite(f.rp)) << cosI;
    ASSERT_GE(f.unpolarized(), 0.0f);
    ASSERT_LE(f.unpolarized(), 1.0f);
    if (!ok) {
      ++total;
      EXPECT_EQ(f.unpolarized(), 1.0f) << "no refracted ray but light transmitted at cos " << cosI;
      EXPECT_EQ(t, Vec3(7.0f)) << "t written under total internal reflection";
      continue;
    }
    ++refracted;
    ASSERT_TRUE(isFinite(t)) << cosI;
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
    EXPECT_LE(t.z, 0.0f);                   // through the surface (or along it, at the critical angle)
    EXPECT_GT(f.unpolarized(), 0.9f) << cosI;  // within ~1e-5 of the critical angle nearly all is reflected
  }
  EXPECT_GT(refracted, 100);  // cos above the critical cosine: refraction
  EXPECT_GT(total, 100);      // below it: total internal reflection
}

TEST(Numerics_Dielectric, GrazingNormalAndRoundedPastOneIncidence) {
  SKIP_WITHOUT_SOLUTION();
  // Grazing from air: everything is reflected; the refracted ray leaves at the critical angle.
  EXPECT_EQ(a3::fresnelDielectric(0.0f, 1.0f, 1.5f).unpolarized(), 1.0f);
  Vec3 t(0.0f);
  ASSERT_TRUE(a3::refract(incoming(0.0f), Vec3(0, 0, 1), 1.0f / 1.5f, t));
  EXPECT_NEAR(t.x, 1.0f / 1.5f, 1e-6f);  // sin(theta_t) = 1 / 1.5
  EXPECT_NEAR(glm::length(t), 1.0f, 1e-6f);
  // Normal incidence, and cos(theta_i) a rounding step past 1 or below 0 (a dot product of unit vectors).
  for (float c : {1.0f, std::nextafter(1.0f, 2.0f), 1.0000005f}) {
    EXPECT_NEAR(a3::fresnelDielectric(c, 1.0f, 1.5f).unpolarized(), 0.04f, 1e-6f) << c;
    ASSERT_TRUE(a3::refract(Vec3(0, 0, -c), Vec3(0, 0, 1), 1.0f / 1.5f, t));
    EXPECT_TRUE(isFinite(t));
    EXPECT_NEAR(t.z, -1.0f, 1e-6f);
  }
  EXPECT_EQ(a3::fresnelDielectric(-1e-7f, 1.0f, 1.5f).unpolarized(), 1.0f);
}

TEST(Numerics_Dielectric, EqualIndicesAreNoInterfaceAtAnyAngle) {
  SKIP_WITHOUT_SOLUTION();
  // Glass against the same glass (nested dielectrics of one medium): nothing reflects, nothing bends,
  // at grazing incidence too.
  for (float c : {1.0f, 0.5f, 0.01f, 1e-6f, 0.0f}) {
    const a3::FresnelTerms f = a3::fresnelDielectric(c, 1.5f, 1.5f);
    EXPECT_NEAR(f.rs, 0.0f, 1e-6f) << c;
    EXPECT_NEAR(f.rp, 0.0f, 1e-6f) << c;
    Vec3 t(0.0f);
    const Vec3 d = incoming(c);
    ASSERT_TRUE(a3::refract(d, Vec3(0, 0, 1), 1.0f, t)) << c;
    EXPECT_NEAR(glm::length(t - d), 0.0f, 1e-5f) << c;
  }
}

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
