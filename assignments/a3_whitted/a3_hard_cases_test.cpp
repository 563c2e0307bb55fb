// The dielectric's hard cases, graded for the task that owns each function:
// refraction (A3.2) and the Fresnel equations (A3.3) float by float around the
// critical angle, at grazing and normal incidence, with cos(theta_i) rounded
// past 1, and with equal indices on both sides (nested media of one glass: no
// interface at all). Each failure says which case broke and why it matters.
#include <cmath>

#include <gtest/gtest.h>

#include "a3_tasks.h"
#include "test_support.h"

namespace ll {
namespace {

Vec3 incoming(float cosI) {  // unit, towards the surface z = 0 whose normal is +z
  return Vec3(std::sqrt(std::max(0.0f, 1.0f - cosI * cosI)), 0.0f, -cosI);
}

// cos(theta_i) from 256 floats below the critical cosine of glass to air up to 256 above it.
template <class F>
void aroundTheCriticalAngle(F&& each) {
  const float eta = 1.5f;
  const float cosCritical = std::sqrt(1.0f - 1.0f / (eta * eta));  // cos(41.81 deg)
  float cosI = cosCritical;
  for (int k = 0; k < 256; ++k) cosI = std::nextafter(cosI, 0.0f);
  for (int k = 0; k < 512; ++k, cosI = std::nextafter(cosI, 1.0f)) each(cosI, k - 256);
}

TEST(A3_2_HardCases, AroundTheCriticalAngleFloatByFloat) {
  SCOPED_TRACE(
      "hard case: glass to air, float by float around the critical angle. Beyond it refract must report total "
      "internal reflection (false, t untouched): sqrt of a negative gives a NaN direction that blackens pixels. "
      "Before it, a unit direction through the surface.");
  int refracted = 0, total = 0;
  aroundTheCriticalAngle([&](float cosI, int step) {
    Vec3 t(7.0f);
    const bool ok = a3::refract(incoming(cosI), Vec3(0, 0, 1), 1.5f, t);
    const double sin2T = 1.5 * 1.5 * (1.0 - static_cast<double>(cosI) * static_cast<double>(cosI));  // in double
    if (!ok) {
      ++total;
      EXPECT_EQ(t, Vec3(7.0f)) << "t written under total internal reflection at cos " << cosI;
      EXPECT_GT(sin2T, 1.0 - 1e-5) << "total internal reflection reported well before the critical angle, cos "
                                   << cosI << " (" << step << " floats from it)";
      return;
    }
    ++refracted;
    ASSERT_TRUE(isFinite(t)) << "a NaN or Inf direction at cos " << cosI << " (" << step << " floats from it)";
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f) << cosI;
    EXPECT_LE(t.z, 1e-6f) << "not through the surface at cos " << cosI;
    EXPECT_LT(sin2T, 1.0 + 1e-5) << "refracted beyond the critical angle, cos " << cosI;
  });
  EXPECT_GT(refracted, 100) << "above the critical cosine light refracts";
  EXPECT_GT(total, 100) << "below it, total internal reflection";
}

TEST(A3_2_HardCases, GrazingAndNormalIncidenceAndEqualIndices) {
  SCOPED_TRACE(
      "hard case: grazing incidence from air (the ray leaves at the critical angle), cos(theta_i) rounded a "
      "step past 1 (a dot product of unit vectors), and equal indices (nothing bends): no NaN, no false "
      "total internal reflection.");
  Vec3 t(0.0f);
  ASSERT_TRUE(a3::refract(incoming(0.0f), Vec3(0, 0, 1), 1.0f / 1.5f, t)) << "grazing from air";
  EXPECT_NEAR(t.x, 1.0f / 1.5f, 1e-6f) << "sin(theta_t) = 1 / 1.5 at grazing incidence";
  EXPECT_NEAR(glm::length(t), 1.0f, 1e-6f);
  for (float c : {1.0f, std::nextafter(1.0f, 2.0f), 1.0000005f}) {
    ASSERT_TRUE(a3::refract(Vec3(0, 0, -c), Vec3(0, 0, 1), 1.0f / 1.5f, t)) << c;
    EXPECT_TRUE(isFinite(t)) << "cos(theta_i) = " << c;
    EXPECT_NEAR(t.z, -1.0f, 1e-6f) << c;
  }
  for (float c : {1.0f, 0.5f, 0.01f, 1e-6f, 0.0f}) {
    const Vec3 d = incoming(c);
    ASSERT_TRUE(a3::refract(d, Vec3(0, 0, 1), 1.0f, t)) << "equal indices, cos " << c;
    EXPECT_NEAR(glm::length(t - d), 0.0f, 1e-5f) << "equal indices bend nothing, cos " << c;
  }
}

TEST(A3_3_HardCases, AroundTheCriticalAngleFloatByFloat) {
  SCOPED_TRACE(
      "hard case: glass to air, float by float around the critical angle: the reflectances stay finite and in "
      "[0, 1], and are 1 beyond it (total internal reflection), where cos(theta_t) would be the root of a "
      "negative number.");
  // The control, well before the critical angle: most light leaves the glass.
  ASSERT_LT(a3::fresnelDielectric(0.95f, 1.5f, 1.0f).unpolarized(), 0.2f) << "cos(theta_i) = 0.95, glass to air";
  aroundTheCriticalAngle([&](float cosI, int step) {
    const a3::FresnelTerms f = a3::fresnelDielectric(cosI, 1.5f, 1.0f);
    ASSERT_TRUE(std::isfinite(f.rs) && std::isfinite(f.rp)) << "NaN at cos " << cosI << " (" << step << " floats)";
    ASSERT_GE(f.unpolarized(), 0.0f) << cosI;
    ASSERT_LE(f.unpolarized(), 1.0f) << cosI;
    const double sin2T = 1.5 * 1.5 * (1.0 - static_cast<double>(cosI) * static_cast<double>(cosI));
    if (sin2T > 1.0 + 1e-5) {
      EXPECT_EQ(f.unpolarized(), 1.0f) << "beyond the critical angle, cos " << cosI;
    }
    if (sin2T < 1.0 - 1e-3) {
      EXPECT_LT(f.unpolarized(), 1.0f) << "before the critical angle, cos " << cosI;
    }
  });
}

TEST(A3_3_HardCases, GrazingNormalRoundedAndEqualIndices) {
  SCOPED_TRACE(
      "hard case: grazing incidence reflects everything; normal incidence gives 0.04 for glass even with "
      "cos(theta_i) rounded past 1 or a hair below 0; equal indices are no interface at any angle (nested "
      "media of one glass), grazing included -- 0/0 there must not become NaN.");
  EXPECT_EQ(a3::fresnelDielectric(0.0f, 1.0f, 1.5f).unpolarized(), 1.0f) << "grazing from air";
  for (float c : {1.0f, std::nextafter(1.0f, 2.0f), 1.0000005f})
    EXPECT_NEAR(a3::fresnelDielectric(c, 1.0f, 1.5f).unpolarized(), 0.04f, 1e-6f) << "cos " << c;
  EXPECT_EQ(a3::fresnelDielectric(-1e-7f, 1.0f, 1.5f).unpolarized(), 1.0f) << "cos a hair below 0";
  for (float c : {1.0f, 0.5f, 0.01f, 1e-6f, 0.0f}) {
    const a3::FresnelTerms f = a3::fresnelDielectric(c, 1.5f, 1.5f);
    EXPECT_NEAR(f.rs, 0.0f, 1e-6f) << "equal indices, cos " << c;
    EXPECT_NEAR(f.rp, 0.0f, 1e-6f) << "equal indices, cos " << c;
  }
}

}  // namespace
}  // namespace ll
