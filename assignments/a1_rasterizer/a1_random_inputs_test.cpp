// Each A1 task against its reference on inputs drawn from the grading seed
// (testing_support::gradingRng): the autograder's seed is not in the student
// tree, so these inputs cannot be looked up, only computed. Where the task
// fixes the answer exactly (the edge function in double, the depth test), it
// must agree exactly; elsewhere to float rounding.
#include <random>

#include <gtest/gtest.h>

#include "a1_tasks.h"
#include "test_support.h"

namespace ll {
namespace {

using testing_support::byReference;
using testing_support::gradingRng;
using testing_support::randomUnitVector;

TEST(A1_1_RandomInputs, AgreesWithTheReference) {
  std::mt19937 rng = gradingRng(101);
  std::uniform_real_distribution<float> u(-10.0f, 10.0f), fov(10.0f, 120.0f);
  for (int i = 0; i < 200; ++i) {
    Camera c;
    c.eye = Vec3(u(rng), u(rng), u(rng));
    c.target = c.eye + 3.0f * randomUnitVector(rng);
    c.up = randomUnitVector(rng);
    if (glm::length(glm::cross(glm::normalize(c.target - c.eye), c.up)) < 0.2f) continue;
    c.fovYDeg = fov(rng);
    c.width = 100 + static_cast<int>(rng() % 900);
    c.height = 100 + static_cast<int>(rng() % 900);
    const float near = 0.01f + 0.1f * (u(rng) + 10.0f), far = near + 50.0f;
    const Mat4 expected = byReference("A1.1", [&] { return a1::viewProjection(c, near, far); });
    const Mat4 mine = a1::viewProjection(c, near, far);
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row)
        ASSERT_NEAR(mine[col][row], expected[col][row], 1e-4f * (1.0f + std::abs(expected[col][row])))
            << "matrix element [" << col << "][" << row << "], camera " << i;
  }
}

TEST(A1_2_RandomInputs, AgreesWithTheReferenceExactly) {
  std::mt19937 rng = gradingRng(102);
  std::uniform_real_distribution<float> u(-500.0f, 500.0f);
  for (int i = 0; i < 2000; ++i) {
    Vec2 a(u(rng), u(rng)), b(u(rng), u(rng)), p(u(rng), u(rng));
    if (i % 4 == 0) b.y = a.y;  // horizontal edges: the "top" half of the rule
    if (i % 8 == 1) p = a + 0.5f * (b - a);  // on the edge (to rounding)
    const double e = byReference("A1.2", [&] { return a1::edgeFunction(a, b, p); });
    ASSERT_EQ(a1::edgeFunction(a, b, p), e) << "a (" << a.x << ", " << a.y << "), b (" << b.x << ", " << b.y
                                             << "), p (" << p.x << ", " << p.y << ")";
    const bool topLeft = byReference("A1.2", [&] { return a1::isTopLeft(a, b); });
    ASSERT_EQ(a1::isTopLeft(a, b), topLeft) << "edge (" << a.x << ", " << a.y << ") -> (" << b.x << ", " << b.y << ")";
  }
}

TEST(A1_3_RandomInputs, AgreesWithTheReferenceExactly) {
  std::mt19937 rng = gradingRng(103);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    const float stored0 = u(rng), z = i % 5 == 0 ? stored0 : u(rng);  // ties too
    float mine = stored0, ref = stored0;
    const bool drawRef = byReference("A1.3", [&] { return a1::depthTest(z, ref); });
    ASSERT_EQ(a1::depthTest(z, mine), drawRef) << "z " << z << " against " << stored0;
    ASSERT_EQ(mine, ref) << "the stored depth after z " << z << " against " << stored0;
  }
}

TEST(A1_4_RandomInputs, AgreesWithTheReference) {
  std::mt19937 rng = gradingRng(104);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 n = randomUnitVector(rng);
    Vec3 v = randomUnitVector(rng), l = randomUnitVector(rng);
    if (glm::dot(v, n) < 0.0f) v = -v;  // the viewer's side
    const Rgb irradiance(u(rng) * 5.0f, u(rng) * 5.0f, u(rng) * 5.0f);
    const float shininess = 1.0f + 200.0f * u(rng);
    const a1::LightTerms ref = byReference("A1.4", [&] { return a1::blinnPhong(n, v, l, irradiance, shininess); });
    const a1::LightTerms mine = a1::blinnPhong(n, v, l, irradiance, shininess);
    for (int c = 0; c < 3; ++c) {
      ASSERT_NEAR(mine.diffuse[c], ref.diffuse[c], 1e-4f * (1.0f + ref.diffuse[c])) << "diffuse, case " << i;
      ASSERT_NEAR(mine.specular[c], ref.specular[c], 2e-3f * (1.0f + ref.specular[c])) << "specular, case " << i;
    }
  }
}

TEST(A1_5_RandomInputs, AgreesWithTheReference) {
  std::mt19937 rng = gradingRng(105);
  std::uniform_real_distribution<float> u(0.0f, 1.0f), far(-3.0f, 3.0f), lod(-1.0f, 6.0f);
  Image texture(24, 16);
  for (Rgb& p : texture.pixels()) p = Rgb(u(rng), u(rng), u(rng));
  const a1::MipChain mips(texture);
  for (a1::TextureFilter f : {a1::TextureFilter::Nearest, a1::TextureFilter::Bilinear, a1::TextureFilter::Trilinear})
    for (int i = 0; i < 500; ++i) {
      const Vec2 uv(far(rng), far(rng));
      const float l = lod(rng);
      const Rgb ref = byReference("A1.5", [&] { return a1::sampleTexture(mips, uv, l, f); });
      const Rgb mine = a1::sampleTexture(mips, uv, l, f);
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(mine[c], ref[c], 1e-4f) << "filter " << static_cast<int>(f) << " at uv (" << uv.x << ", " << uv.y
                                            << "), lod " << l;
    }
}

}  // namespace
}  // namespace ll
