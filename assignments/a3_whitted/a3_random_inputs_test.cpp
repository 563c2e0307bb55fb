// A3's functions against their references on inputs drawn from the grading
// seed (the autograder's is not in the student tree), and A3.5 against what
// any robust offset must do. (A3.4 is graded by its ray trees and renders.)
#include <random>

#include <gtest/gtest.h>

#include "a3_tasks.h"
#include "test_support.h"

namespace ll {
namespace {

using testing_support::byReference;
using testing_support::gradingRng;
using testing_support::randomUnitVector;

TEST(A3_1_RandomInputs, AgreesWithTheReference) {
  std::mt19937 rng = gradingRng(301);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 d = randomUnitVector(rng), n = randomUnitVector(rng);
    const Vec3 ref = byReference("A3.1", [&] { return a3::reflect(d, n); });
    const Vec3 mine = a3::reflect(d, n);
    ASSERT_NEAR(glm::length(mine - ref), 0.0f, 1e-5f) << "d " << testing::PrintToString(d) << ", n "
                                                       << testing::PrintToString(n);
  }
}

TEST(A3_2_RandomInputs, AgreesWithTheReference) {
  std::mt19937 rng = gradingRng(302);
  std::uniform_real_distribution<float> index(1.0f, 2.5f);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 n = randomUnitVector(rng);
    Vec3 d = randomUnitVector(rng);
    if (glm::dot(d, n) > 0.0f) d = -d;  // arriving on the normal's side
    const float eta = i % 2 ? index(rng) : 1.0f / index(rng);
    Vec3 ref(0.0f), mine(0.0f);
    const bool refracts = byReference("A3.2", [&] { return a3::refract(d, n, eta, ref); });
    const double eta2 = static_cast<double>(eta) * static_cast<double>(eta);
    const double cosI = static_cast<double>(glm::dot(d, n));
    const double sin2T = eta2 * (1.0 - cosI * cosI);
    if (std::abs(sin2T - 1.0) < 1e-4) continue;  // at the critical angle either answer is right
    ASSERT_EQ(a3::refract(d, n, eta, mine), refracts) << "eta " << eta << ", cos(theta_i) " << -glm::dot(d, n);
    if (refracts) {
      ASSERT_NEAR(glm::length(mine - ref), 0.0f, 1e-4f) << "eta " << eta << ", cos(theta_i) " << -glm::dot(d, n);
    }
  }
}

TEST(A3_3_RandomInputs, AgreesWithTheReference) {
  std::mt19937 rng = gradingRng(303);
  std::uniform_real_distribution<float> cosine(0.0f, 1.0f), index(1.0f, 2.5f);
  for (int i = 0; i < 2000; ++i) {
    const float cosI = cosine(rng), n1 = index(rng), n2 = index(rng);
    const a3::FresnelTerms ref = byReference("A3.3", [&] { return a3::fresnelDielectric(cosI, n1, n2); });
    const a3::FresnelTerms mine = a3::fresnelDielectric(cosI, n1, n2);
    ASSERT_NEAR(mine.rs, ref.rs, 1e-4f) << "cos " << cosI << ", n1 " << n1 << ", n2 " << n2;
    ASSERT_NEAR(mine.rp, ref.rp, 1e-4f) << "cos " << cosI << ", n1 " << n1 << ", n2 " << n2;
  }
}

TEST(A3_5_RandomInputs, OriginsLeaveOnTheRightSideByLittle) {
  // Any robust offset will do: the origin on the side `dir` leaves to, off the surface by more than the
  // point's own rounding error along the normal, and by less than a thousandth of its distance from the
  // world origin plus 1e-3.
  std::mt19937 rng = gradingRng(305);
  std::uniform_real_distribution<float> scale(-5.0f, 5.0f);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 ng = randomUnitVector(rng), dir = randomUnitVector(rng);
    const Vec3 p = std::pow(10.0f, scale(rng)) * randomUnitVector(rng);
    const Ray r = a3::secondaryRay(p, ng, dir);
    const double side = glm::dot(glm::dvec3(r.origin) - glm::dvec3(p), glm::dvec3(ng));
    const double wanted = glm::dot(dir, ng) >= 0.0f ? 1.0 : -1.0;
    // The rounding error of p along ng: half an ulp of each coordinate, weighted by ng.
    const glm::dvec3 dn(ng), dp(p);
    const double pointError = 6e-8 * (std::abs(dn.x * dp.x) + std::abs(dn.y * dp.y) + std::abs(dn.z * dp.z));
    ASSERT_GT(side * wanted, pointError) << "p " << testing::PrintToString(p) << " barely moved or moved to the wrong side";
    ASSERT_LT(std::abs(side), 1e-3 * glm::length(glm::dvec3(p)) + 1e-3) << "p " << testing::PrintToString(p)
                                                                          << " moved too far";
    ASSERT_EQ(r.dir, dir);
  }
}

}  // namespace
}  // namespace ll
