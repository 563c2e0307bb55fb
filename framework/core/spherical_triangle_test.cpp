#include "core/spherical_triangle.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/rng.h"

namespace ll {
namespace {

// The octant's triangle seen from the origin: solid angle pi / 2, projected
// solid angle about z pi / 4, so cos(theta) averages 1/2 over uniform samples.
TEST(SphericalTriangle, OctantSolidAngleAndUniformSamples) {
  const auto t = sphericalTriangle(glm::dvec3(0), {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(t->solidAngle, kPiD / 2.0, 1e-12);
  Rng rng(1, 2);
  const int n = 200000;
  double cosZ = 0.0, xFirst = 0.0;
  for (int k = 0; k < n; ++k) {
    const glm::dvec3 w = sampleSphericalTriangle(*t, glm::dvec2(rng.uniform(), rng.uniform()));
    ASSERT_NEAR(glm::length(w), 1.0, 1e-9);
    ASSERT_GE(w.x, -1e-9);
    ASSERT_GE(w.y, -1e-9);
    ASSERT_GE(w.z, -1e-9);
    cosZ += w.z;
    xFirst += w.x > w.y ? 1.0 : 0.0;  // by symmetry half the samples
  }
  EXPECT_NEAR(cosZ / n, 0.5, 3e-3);
  EXPECT_NEAR(xFirst / n, 0.5, 5e-3);
}

// A thin triangle far away and one seen edge-on: finite, never NaN.
TEST(SphericalTriangle, DegenerateViewsAreRefusedOrFinite) {
  EXPECT_FALSE(sphericalTriangle(glm::dvec3(0), {0, 0, 0}, {1, 0, 0}, {0, 1, 0}).has_value());  // a corner at p
  EXPECT_FALSE(sphericalTriangle(glm::dvec3(0), {1, 0, 0}, {2, 0, 0}, {3, 0, 0}).has_value());  // collinear
  const auto far = sphericalTriangle(glm::dvec3(0), {1e4, 0, 0}, {1e4, 1e-3, 0}, {1e4, 0, 1e-3});
  ASSERT_TRUE(far.has_value());
  EXPECT_NEAR(far->solidAngle, 0.5e-6 / 1e8, 1e-17);
  const glm::dvec3 w = sampleSphericalTriangle(*far, {0.3, 0.7});
  EXPECT_TRUE(std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z));
  EXPECT_NEAR(w.x, 1.0, 1e-9);
}

}  // namespace
}  // namespace ll
