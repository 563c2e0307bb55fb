// A5's functions against their references on inputs drawn from the grading
// seed (the autograder's is not in the student tree): form factors of random
// polygons seen from random points, and one Gauss-Seidel sweep and one shot of
// random small systems.
#include <random>

#include <gtest/gtest.h>

#include "a5_tasks.h"
#include "test_support.h"

namespace ll {
namespace {

using testing_support::byReference;
using testing_support::gradingRng;

TEST(A5_1_RandomInputs, AgreesWithTheReference) {
  std::mt19937 rng = gradingRng(501);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), height(0.2f, 3.0f);
  for (int i = 0; i < 1000; ++i) {
    // A convex polygon (3 to 6 vertices on an ellipse) in the plane z = h, seen from x on z = 0 with a tilted normal.
    const int count = 3 + static_cast<int>(rng() % 4);
    const float h = height(rng), rx = 0.3f + std::abs(u(rng)), ry = 0.3f + std::abs(u(rng)), phase = 3.0f * u(rng);
    std::vector<Vec3> poly;
    for (int k = 0; k < count; ++k) {
      const float a = phase + 6.2831853f * static_cast<float>(k) / static_cast<float>(count);
      poly.emplace_back(u(rng) * 0.1f + rx * std::cos(a), u(rng) * 0.1f + ry * std::sin(a), h);
    }
    if (i % 2) std::reverse(poly.begin(), poly.end());  // either winding
    const Vec3 x(u(rng), u(rng), 0.0f);
    const Vec3 n = glm::normalize(Vec3(0.3f * u(rng), 0.3f * u(rng), 1.0f));
    const float ref = byReference("A5.1", [&] { return a5::pointToPolygonFormFactor(x, n, poly.data(), count); });
    const float mine = a5::pointToPolygonFormFactor(x, n, poly.data(), count);
    ASSERT_NEAR(mine, ref, 1e-4f + 1e-4f * ref) << count << "-gon at height " << h << ", case " << i;
  }
}

// A random system of n patches whose rows sum to below 1: reflectance up to 0.9.
struct RandomSystem {
  std::vector<a5::Patch> patches;
  a5::FormFactors f;
  RandomSystem(std::mt19937& rng, uint32_t n) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (uint32_t i = 0; i < n; ++i) {
      a5::Patch p;
      p.area = 0.5f + u(rng);
      p.emission = i % 5 == 0 ? Rgb(u(rng), u(rng), u(rng)) * 10.0f : Rgb(0.0f);
      p.reflectance = Rgb(u(rng), u(rng), u(rng)) * 0.9f;
      patches.push_back(p);
    }
    f.rowStart.push_back(0);
    for (uint32_t i = 0; i < n; ++i) {
      std::vector<float> row(n, 0.0f);
      float sum = 0.0f;
      for (uint32_t j = 0; j < n; ++j)
        if (j != i && u(rng) < 0.5f) sum += (row[j] = u(rng));
      for (uint32_t j = 0; j < n; ++j)
        if (row[j] > 0.0f) {
          f.column.push_back(j);
          f.value.push_back(0.95f * row[j] / sum);
        }
      f.rowStart.push_back(static_cast<uint32_t>(f.column.size()));
    }
  }
  std::vector<Rgb> emissions() const {
    std::vector<Rgb> e;
    for (const a5::Patch& p : patches) e.push_back(p.emission);
    return e;
  }
};

TEST(A5_2_RandomInputs, OneSweepAgreesWithTheReference) {
  std::mt19937 rng = gradingRng(502);
  for (int trial = 0; trial < 50; ++trial) {
    const RandomSystem s(rng, 5 + static_cast<uint32_t>(rng() % 40));
    const a5::RadiositySystem system{s.patches, s.f};
    const std::vector<Rgb> start = s.emissions();
    std::vector<Rgb> ref = start, mine = start;
    const float changeRef = byReference("A5.2", [&] { return a5::gaussSeidelSweep(system, ref); });
    const float change = a5::gaussSeidelSweep(system, mine);
    ASSERT_NEAR(change, changeRef, 1e-4f * (1.0f + changeRef)) << "the returned change, system " << trial;
    for (size_t i = 0; i < mine.size(); ++i)
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(mine[i][c], ref[i][c], 1e-4f * (1.0f + ref[i][c])) << "B of patch " << i << ", system " << trial;
  }
}

TEST(A5_3_RandomInputs, OneShotAgreesWithTheReference) {
  std::mt19937 rng = gradingRng(503);
  for (int trial = 0; trial < 50; ++trial) {
    const RandomSystem s(rng, 5 + static_cast<uint32_t>(rng() % 40));
    const a5::RadiositySystem system{s.patches, s.f};
    const std::vector<Rgb> start = s.emissions();
    std::vector<Rgb> refB = start, refUnshot = start, b = start, unshot = start;
    for (int shot = 0; shot < 3; ++shot) {
      const int refShooter = byReference("A5.3", [&] { return a5::shootLargest(system, refB, refUnshot); });
      ASSERT_EQ(a5::shootLargest(system, b, unshot), refShooter) << "the shooter of shot " << shot << ", system " << trial;
      for (size_t i = 0; i < b.size(); ++i)
        for (int c = 0; c < 3; ++c) {
          ASSERT_NEAR(b[i][c], refB[i][c], 1e-4f * (1.0f + refB[i][c])) << "B of patch " << i << " after shot " << shot;
          ASSERT_NEAR(unshot[i][c], refUnshot[i][c], 1e-4f * (1.0f + refUnshot[i][c]))
              << "unshot of patch " << i << " after shot " << shot;
        }
    }
  }
}

}  // namespace
}  // namespace ll
