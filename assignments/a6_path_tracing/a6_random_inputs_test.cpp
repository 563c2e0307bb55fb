// A6's functions on inputs drawn from the grading seed (the autograder's is
// not in the student tree): Russian roulette against its reference (the rule
// fixes the answer), and the cosine density's moments from seeded samples
// (any correct mapping of [0,1)^2 onto the hemisphere has them).
#include <random>

#include <gtest/gtest.h>

#include "a6_tasks.h"
#include "test_support.h"

namespace ll {
namespace {

using testing_support::byReference;
using testing_support::gradingRng;

TEST(A6_1_RandomInputs, SeededSamplesHaveTheCosineMoments) {
  std::mt19937 rng = gradingRng(601);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  constexpr int kN = 200000;
  double z = 0.0, z2 = 0.0, x = 0.0, y = 0.0;
  for (int i = 0; i < kN; ++i) {
    const Vec3 d = a6::sampleCosineHemisphere(Vec2(u(rng), u(rng)));
    ASSERT_NEAR(glm::length(d), 1.0f, 1e-4f);
    const glm::dvec3 e(d);
    z += e.z;
    z2 += e.z * e.z;
    x += e.x;
    y += e.y;
  }
  // E[z] = 2/3, E[z^2] = 1/2, E[x] = E[y] = 0 for the density cos / pi; 5 standard errors of these sums.
  EXPECT_NEAR(z / kN, 2.0 / 3.0, 5.0 * 0.2357 / std::sqrt(kN));
  EXPECT_NEAR(z2 / kN, 0.5, 5.0 * 0.2887 / std::sqrt(kN));
  EXPECT_NEAR(x / kN, 0.0, 5.0 * 0.5 / std::sqrt(kN));
  EXPECT_NEAR(y / kN, 0.0, 5.0 * 0.5 / std::sqrt(kN));
}

TEST(A6_3_RandomInputs, AgreesWithTheReference) {
  std::mt19937 rng = gradingRng(603);
  std::uniform_real_distribution<float> u(0.0f, 1.0f), t(0.0f, 1.2f);
  for (int i = 0; i < 5000; ++i) {
    const Rgb start(t(rng) * (i % 7 == 0 ? 0.02f : 1.0f), t(rng), t(rng));
    const float x = u(rng);
    Rgb ref = start, mine = start;
    const bool goesOn = byReference("A6.3", [&] { return a6::russianRoulette(ref, x); });
    ASSERT_EQ(a6::russianRoulette(mine, x), goesOn) << "throughput " << testing::PrintToString(start) << ", u " << x;
    if (!goesOn) continue;
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(mine[c], ref[c], 1e-5f * (1.0f + ref[c])) << "the survivor's throughput, from "
                                                             << testing::PrintToString(start);
  }
}

}  // namespace
}  // namespace ll
