// Assignment 1 tests: the tasks on exact inputs (A1_1 ... A1_5), the pipeline
// on analytic pictures (coverage with the fill rule, perspective-correct
// texture coordinates, Blinn-Phong values at every pixel), and the technique
// against ray casting where both must agree.
#include <atomic>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "a1_tasks.h"
#include "metrics/image_metrics.h"
#include "modules/registry.h"
#include "rasterizer.h"
#include "render/render_job.h"
#include "scene/scene_loader.h"
#include "core/subprocess.h"
#include "test_support.h"

namespace ll {
namespace {

using testing_support::implemented;

// --- A1.1 projection ------------------------------------------------------------

TEST(A1_1_Projection, MatchesLookAtTimesPerspective) {
  Camera c;
  c.eye = Vec3(1.0f, 2.0f, 7.0f);
  c.target = Vec3(-0.5f, 0.3f, 0.0f);
  c.up = Vec3(0.1f, 1.0f, 0.0f);
  c.fovYDeg = 38.0f;
  c.width = 320;
  c.height = 200;
  Mat4 m(1.0f);
  ASSERT_TRUE(implemented("A1.1", [&] { m = a1::viewProjection(c, 0.1f, 100.0f); }));
  const Mat4 expected = glm::perspective(glm::radians(38.0f), 1.6f, 0.1f, 100.0f) * glm::lookAt(c.eye, c.target, c.up);
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row) EXPECT_NEAR(m[col][row], expected[col][row], 1e-5f) << col << "," << row;
  // The target lands at the centre of the screen; the near and far planes at NDC z = -1 and +1.
  const Vec4 t = m * Vec4(c.target, 1.0f);
  EXPECT_NEAR(t.x / t.w, 0.0f, 1e-6f);
  EXPECT_NEAR(t.y / t.w, 0.0f, 1e-6f);
  const Vec3 forward = glm::normalize(c.target - c.eye);
  const Vec4 n = m * Vec4(c.eye + 0.1f * forward, 1.0f), f = m * Vec4(c.eye + 100.0f * forward, 1.0f);
  EXPECT_NEAR(n.z / n.w, -1.0f, 1e-4f);
  EXPECT_NEAR(f.z / f.w, 1.0f, 1e-4f);
}

// --- A1.2 edge functions and the fill rule -------------------------------------

TEST(A1_2_EdgeFunction, TwiceTheSignedAreaAndTheTopLeftRule) {
  double e = 0.0;
  ASSERT_TRUE(implemented("A1.2", [&] { e = a1::edgeFunction(Vec2(0, 0), Vec2(4, 0), Vec2(0, 3)); }));
  EXPECT_EQ(e, 12.0);  // y down: (0,3) is clockwise from (0,0)->(4,0) on screen
  EXPECT_EQ(a1::edgeFunction(Vec2(0, 0), Vec2(0, 3), Vec2(4, 0)), -12.0);
  EXPECT_EQ(a1::edgeFunction(Vec2(1, 1), Vec2(3, 3), Vec2(2, 2)), 0.0);  // on the edge: exactly 0
  // Exact for any float inputs: the two directions of an edge give opposite values.
  const Vec2 a(0.1f, 7.3f), b(913.7f, 0.3f), p(456.9f, 3.8f);
  EXPECT_EQ(a1::edgeFunction(a, b, p), -a1::edgeFunction(b, a, p));
  // Triangle (0,0), (4,0), (0,3) has positive area: its top edge runs right,
  // its left edge runs up; the hypotenuse is neither.
  EXPECT_TRUE(a1::isTopLeft(Vec2(0, 0), Vec2(4, 0)));
  EXPECT_TRUE(a1::isTopLeft(Vec2(0, 3), Vec2(0, 0)));
  EXPECT_FALSE(a1::isTopLeft(Vec2(4, 0), Vec2(0, 3)));
  EXPECT_FALSE(a1::isTopLeft(Vec2(4, 3), Vec2(0, 3)));  // a bottom edge
}

// --- A1.3 z-buffer --------------------------------------------------------------

TEST(A1_3_DepthTest, KeepsTheNearestAndRejectsTies) {
  float stored = 1.0f;
  bool drawn = false;
  ASSERT_TRUE(implemented("A1.3", [&] { drawn = a1::depthTest(0.5f, stored); }));
  EXPECT_TRUE(drawn);
  EXPECT_EQ(stored, 0.5f);
  EXPECT_FALSE(a1::depthTest(0.7f, stored));
  EXPECT_FALSE(a1::depthTest(0.5f, stored));  // equal depth: the first one drawn stays
  EXPECT_EQ(stored, 0.5f);
  EXPECT_TRUE(a1::depthTest(0.2f, stored));
  EXPECT_EQ(stored, 0.2f);
}

// --- A1.4 Blinn-Phong -------------------------------------------------------------

TEST(A1_4_BlinnPhong, PeakWhereNDotHIsOneAndTheFormulaElsewhere) {
  const Vec3 n(0, 0, 1);
  const Vec3 l = glm::normalize(Vec3(1, 0, 1));  // 45 degrees
  const Vec3 v = glm::normalize(Vec3(-1, 0, 1));  // the mirror direction: h = n
  a1::LightTerms t;
  ASSERT_TRUE(implemented("A1.4", [&] { t = a1::blinnPhong(n, v, l, Rgb(2.0f), 40.0f); }));
  EXPECT_NEAR(t.diffuse.r, 2.0f * std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(t.specular.g, 2.0f, 1e-5f);  // n.h = 1 (to rounding): the peak, I/r^2 itself
  const Vec3 v2 = glm::normalize(Vec3(0, 0.3f, 1));
  const a1::LightTerms off = a1::blinnPhong(n, v2, l, Rgb(2.0f), 40.0f);
  const float nh = glm::dot(n, glm::normalize(v2 + l));
  EXPECT_NEAR(off.specular.b, 2.0f * std::pow(nh, 40.0f), 1e-6f);
  const a1::LightTerms behind = a1::blinnPhong(n, v, -l, Rgb(2.0f), 40.0f);  // light below the surface
  EXPECT_EQ(behind.diffuse, Rgb(0.0f));
  EXPECT_EQ(behind.specular, Rgb(0.0f));
}

// --- A1.5 texture sampling ----------------------------------------------------------

Image rampTexture() {  // 4 x 2 texels, texel (i, j) = (i, j, 0); row 0 is the top
  Image img(4, 2);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) img.at(i, j) = Rgb(static_cast<float>(i), static_cast<float>(j), 0.0f);
  return img;
}

TEST(A1_5_Texture, NearestBilinearTrilinearAndRepeat) {
  const a1::MipChain mips(rampTexture());
  ASSERT_EQ(mips.levels(), 3);  // 4x2, 2x1, 1x1
  EXPECT_EQ(mips.level(2).at(0, 0), Rgb(1.5f, 0.5f, 0.0f));  // the mean
  Rgb c;
  // Texel (1, 0) (top row) has its centre at uv (1.5/4, 1 - 0.5/2).
  ASSERT_TRUE(implemented(
      "A1.5", [&] { c = a1::sampleTexture(mips, Vec2(0.375f, 0.75f), 0.0f, a1::TextureFilter::Nearest); }));
  EXPECT_EQ(c, Rgb(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(a1::sampleTexture(mips, Vec2(0.45f, 0.9f), 0.0f, a1::TextureFilter::Nearest), Rgb(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(a1::sampleTexture(mips, Vec2(1.375f, -0.25f), 0.0f, a1::TextureFilter::Nearest), Rgb(1.0f, 0.0f, 0.0f));
  // Bilinear halfway between texel centres (1,0), (2,0), (1,1), (2,1): their mean.
  const Rgb mid = a1::sampleTexture(mips, Vec2(0.5f, 0.5f), 0.0f, a1::TextureFilter::Bilinear);
  EXPECT_NEAR(mid.r, 1.5f, 1e-5f);
  EXPECT_NEAR(mid.g, 0.5f, 1e-5f);
  // Repeat: u = 0 lies between texel 3 (wrapped) and texel 0.
  EXPECT_NEAR(a1::sampleTexture(mips, Vec2(0.0f, 0.75f), 0.0f, a1::TextureFilter::Bilinear).r, 1.5f, 1e-5f);
  // Trilinear: lod 0 is bilinear on level 0, lod 1 bilinear on level 1, lod 0.5 halfway.
  const Vec2 uv(0.3f, 0.6f);
  const Rgb l0 = a1::sampleTexture(mips, uv, 0.0f, a1::TextureFilter::Trilinear);
  const Rgb l1 = a1::sampleTexture(mips, uv, 1.0f, a1::TextureFilter::Trilinear);
  const Rgb half = a1::sampleTexture(mips, uv, 0.5f, a1::TextureFilter::Trilinear);
  EXPECT_EQ(l0, a1::sampleTexture(mips, uv, 0.0f, a1::TextureFilter::Bilinear));
  EXPECT_NEAR(half.r, 0.5f * (l0.r + l1.r), 1e-5f);
  EXPECT_NEAR(a1::sampleTexture(mips, uv, 9.0f, a1::TextureFilter::Trilinear).r, 1.5f, 1e-5f);  // clamped to 1x1
}

// --- the pipeline -------------------------------------------------------------------

// Draws screen-space triangles given in sample coordinates (x right, y down)
// on a 64 x 64 target, counting the fragments each sample receives.
class CountingShader final : public a1::Shader {
 public:
  CountingShader(std::vector<Vec2> points, int size) : points_(std::move(points)), size_(size), hits_(size * size) {}
  Vec4 vertex(int index, int, a1::Varyings& out) const override {
    const Vec2 p = points_[static_cast<size_t>(index)];
    const float s = static_cast<float>(size_);
    out.position = Vec3(p, 0.0f);
    const float z = 0.9f - 1e-4f * static_cast<float>(index / 3);  // exact screen positions: s is a power of 2
    return Vec4(p.x / s * 2.0f - 1.0f, 1.0f - p.y / s * 2.0f, z, 1.0f);
  }
  Rgb fragment(const a1::Fragment& f) const override {
    ++hits_[static_cast<size_t>(f.sample.y * size_ + f.sample.x)];
    return Rgb(1.0f);
  }
  int hits(int x, int y) const { return hits_[static_cast<size_t>(y * size_ + x)].load(); }
  int drawCalls() const { return static_cast<int>(points_.size()); }

 private:
  std::vector<Vec2> points_;
  int size_;
  mutable std::vector<std::atomic<int>> hits_;
};

// Rasterizes `points` (3 per triangle) at 1 sample per pixel; returns the shader.
std::unique_ptr<CountingShader> drawCounting(std::vector<Vec2> points) {
  auto shader = std::make_unique<CountingShader>(std::move(points), 64);
  FrameBuffer fb(64, 64);
  a1::RasterSettings s;
  s.width = s.height = 64;
  const std::atomic<bool> cancel{false};
  // One frame per triangle: within a frame the fragment stage runs once per
  // sample (for the fragment that wins the z-buffer), so a sample covered twice
  // shows up only across frames.
  for (int first = 0; first < shader->drawCalls(); first += 3)
    a1::rasterize(*shader, {a1::DrawCall{first, 3, 0}}, s, fb, cancel);
  return shader;
}

// Two triangles per cell of a grid over [lo, hi]^2; corners jittered by `jitter` (inner ones only).
std::vector<Vec2> tessellatedSquare(float lo, float hi, int cells, float jitter) {
  const auto corner = [&](int i, int j) {
    Vec2 p(lo + (hi - lo) * static_cast<float>(i) / static_cast<float>(cells),
           lo + (hi - lo) * static_cast<float>(j) / static_cast<float>(cells));
    if (i > 0 && i < cells && j > 0 && j < cells)  // a deterministic "random" jitter
      p += jitter * Vec2(std::sin(static_cast<float>(i * 7 + j * 13)), std::cos(static_cast<float>(i * 11 + j * 5)));
    return p;
  };
  std::vector<Vec2> pts;
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      const Vec2 a = corner(i, j), b = corner(i + 1, j), c = corner(i + 1, j + 1), d = corner(i, j + 1);
      if ((i + j) % 2 == 0)
        pts.insert(pts.end(), {a, b, c, a, c, d});  // alternate diagonals and windings
      else
        pts.insert(pts.end(), {b, a, d, b, d, c});
    }
  return pts;
}

void expectEverySampleOnce(const CountingShader& s, float lo, float hi) {
  int total = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
      // Inside the half-open square [lo, hi)^2 (the top-left rule on its outline).
      const int expected = (cx >= lo && cx < hi && cy >= lo && cy < hi) ? 1 : 0;
      ASSERT_EQ(s.hits(x, y), expected) << "sample " << x << "," << y;
      total += s.hits(x, y);
    }
  EXPECT_EQ(static_cast<float>(total), (hi - lo) * (hi - lo));
}

TEST(A1_2_Pipeline, TessellatedSquareCoversExactlyItsAreaEdgesThroughSampleCentres) {
  // Square [8.5, 56.5]^2: every edge of the 12 x 12 grid runs through sample centres.
  expectEverySampleOnce(*drawCounting(tessellatedSquare(8.5f, 56.5f, 12, 0.0f)), 8.5f, 56.5f);
}

TEST(A1_2_Pipeline, JitteredTessellationHasNoGapsOrDoubleHits) {
  expectEverySampleOnce(*drawCounting(tessellatedSquare(4.5f, 60.5f, 14, 1.3f)), 4.5f, 60.5f);
}

TEST(A1_2_Pipeline, FanAroundASampleCentreDrawsItOnce) {
  std::vector<Vec2> pts;
  const Vec2 c(32.5f, 32.5f);
  for (int k = 0; k < 16; ++k) {  // 16 triangles around the sample centre (32, 32)
    // (k + 1) % 16: the last triangle closes the fan on the first one's vertex, bit for bit.
    const float a0 = 2.0f * kPi * static_cast<float>(k) / 16.0f;
    const float a1 = 2.0f * kPi * static_cast<float>((k + 1) % 16) / 16.0f;
    pts.insert(pts.end(), {c, c + 20.0f * Vec2(std::cos(a0), std::sin(a0)), c + 20.0f * Vec2(std::cos(a1), std::sin(a1))});
  }
  const auto s = drawCounting(pts);
  EXPECT_EQ(s->hits(32, 32), 1);
  for (int y = 14; y < 50; ++y)
    for (int x = 14; x < 50; ++x) ASSERT_LE(s->hits(x, y), 1) << x << "," << y;
}

TEST(A1_2_Pipeline, SupersamplingAveragesTheCoveredFraction) {
  // A square whose left edge halves pixel column 10 at 16 samples per pixel.
  CountingShader shader({Vec2(42.0f, 0.0f), Vec2(256.0f, 0.0f), Vec2(256.0f, 256.0f), Vec2(42.0f, 0.0f),
                         Vec2(256.0f, 256.0f), Vec2(42.0f, 256.0f)},
                        256);  // points on the 4x4-supersampled 64 x 64 grid
  FrameBuffer fb(64, 64);
  a1::RasterSettings s;
  s.width = s.height = 64;
  s.scale = 4;
  const std::atomic<bool> cancel{false};
  a1::rasterize(shader, {a1::DrawCall{0, 6, 0}}, s, fb, cancel);
  fb.completePass();
  const Image img = fb.resolve(false);
  EXPECT_EQ(img.at(9, 5), Rgb(0.0f));
  EXPECT_EQ(img.at(10, 5), Rgb(0.5f));  // 8 of 16 samples
  EXPECT_EQ(img.at(11, 5), Rgb(1.0f));
}

TEST(A1_2_Pipeline, NearPlaneClippingKeepsTheVisiblePart) {
  // A floor running from behind the camera to far ahead: without clipping
  // the vertex behind the eye (w < 0) would flip the triangle across the screen.
  const std::string scene = R"({
    "camera": {"eye": [0, 1, 0], "target": [0, 1, -1], "up": [0, 1, 0], "fov_y_deg": 60, "width": 32, "height": 32},
    "background": [0, 0, 0], "ambient": [1, 1, 1],
    "materials": {"m": {"ka": [1, 1, 1]}},
    "lights": [],
    "objects": [{"type": "quad", "material": "m", "vertices": [[-50, 0, 10], [50, 0, 10], [50, 0, -100], [-50, 0, -100]]}]
  })";
  const Scene s = parseJsonScene(scene, "clip.json", ".");
  const auto accel = buildAccelerator(findAccelerator("none"), ParamSet("none", findAccelerator("none").params), s.geometry);
  const TechniqueInfo& info = findTechnique("blinn-phong");
  const auto technique = info.make();
  RenderSettings settings;
  settings.width = settings.height = 32;
  const ParamSet params(info.name, info.params);
  RenderJob job(s, *accel, *technique, params, settings);
  job.run();
  const Image img = job.frame().resolve(false);
  for (int x = 0; x < 32; ++x) {
    EXPECT_EQ(img.at(x, 31), Rgb(1.0f)) << x;  // the floor below the horizon
    EXPECT_EQ(img.at(x, 0), Rgb(0.0f)) << x;   // the sky above it
  }
}

// --- the technique on analytic scenes -------------------------------------------------

struct Rendered {
  Scene scene;
  Image image;
  RenderStats stats;
};

Rendered renderText(const std::string& text, const std::string& technique,
                    const std::vector<std::pair<std::string, std::string>>& sets, int spp = 1) {
  Rendered r{parseJsonScene(text, "test.json", std::string(LIGHTLAB_DATA_DIR) + "/scenes"), {}, {}};
  const AcceleratorInfo& none = findAccelerator("none");
  const auto accel = buildAccelerator(none, ParamSet(none.name, none.params), r.scene.geometry);
  const TechniqueInfo& info = findTechnique(technique);
  ParamSet params(info.name, info.params);
  for (const auto& [k, v] : sets) params.set(k, v);
  const auto t = info.make();
  RenderSettings settings;
  settings.width = r.scene.camera.width;
  settings.height = r.scene.camera.height;
  settings.spp = spp;
  RenderJob job(r.scene, *accel, *t, params, settings);
  job.run();
  r.image = job.frame().resolve(false);
  r.stats = job.stats();
  return r;
}

// A square in the plane z = 0 seen obliquely, one point light.
std::string planeScene(const std::string& material) {
  return R"({
    "camera": {"eye": [0.6, -2.2, 2.4], "target": [0, 0, 0], "up": [0, 0, 1], "fov_y_deg": 50, "width": 64, "height": 48},
    "background": [0, 0, 0], "ambient": [0.2, 0.2, 0.2],
    "materials": {"m": )" +
         material + R"(},
    "lights": [{"type": "point", "position": [-0.4, 0.9, 1.5], "intensity": [3, 3, 3]}],
    "objects": [{"type": "quad", "material": "m", "vertices": [[-2, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0]]}]
  })";
}

// L at the plane z = 0 seen through the centre of pixel (x, y); false if the ray misses it.
bool analyticPlane(const Scene& s, int x, int y, Rgb& out) {
  const CameraFrame frame(s.camera);
  const Ray ray = referenceCameraRay(s.camera, frame, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
  const float t = -ray.origin.z / ray.dir.z;
  const Vec3 p = ray.origin + t * ray.dir;
  if (!(t > 0.0f) || std::abs(p.x) > 1.95f || std::abs(p.y) > 1.95f) return false;
  const Material& m = s.materials[0];
  const Light& light = s.lights[0];
  const Vec3 n(0, 0, 1), d = light.position - p, l = glm::normalize(d), v = glm::normalize(s.camera.eye - p);
  const Rgb e = light.intensity / glm::dot(d, d);
  const float nl = std::max(0.0f, glm::dot(n, l));
  const float nh = std::max(0.0f, glm::dot(n, glm::normalize(l + v)));
  out = m.ka * s.ambient + m.kd * e * nl + (nl > 0.0f ? m.ks * e * std::pow(nh, m.shininess) : Rgb(0.0f));
  return true;
}

void expectAnalyticPlane(const Rendered& r, float tolerance) {
  int checked = 0;
  for (int y = 0; y < r.image.height(); ++y)
    for (int x = 0; x < r.image.width(); ++x) {
      Rgb expected;
      if (!analyticPlane(r.scene, x, y, expected)) continue;
      const Rgb got = r.image.at(x, y);
      ASSERT_NEAR(got.r, expected.r, tolerance * std::max(1.0f, expected.r)) << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 1000);
}

TEST(A1_4_Render, DiffuseOnlyEqualsKdTimesCosineTimesIOverRSquared) {
  for (const char* shading : {"phong", "flat", "gouraud"}) {
    SCOPED_TRACE(shading);
    const Rendered r = renderText(planeScene(R"({"ka": [0.1, 0.1, 0.1], "kd": [0.7, 0.5, 0.3]})"), "blinn-phong",
                                  {{"shading", shading}});
    if (std::string(shading) == "gouraud") {
      // Per-vertex lighting interpolated: exact at the four corners only; check it is close and smooth.
      const ImageError e = compareImages(r.image, renderText(planeScene(R"({"ka": [0.1, 0.1, 0.1], "kd": [0.7, 0.5, 0.3]})"),
                                                             "blinn-phong", {{"shading", "phong"}})
                                                      .image);
      EXPECT_GT(e.rmse, 1e-3);  // the lecture's point: Gouraud is not per-pixel lighting
      continue;
    }
    expectAnalyticPlane(r, 2e-4f);
  }
}

TEST(A1_4_Render, SpecularPeakSitsWhereNDotHIsOneAndMatchesTheFormula) {
  const Rendered r = renderText(planeScene(R"({"ks": [1, 1, 1], "shininess": 40})"), "blinn-phong", {});
  expectAnalyticPlane(r, 2e-3f);
  // Divide out ks * I / r^2: what is left is (n.h)^p, whose maximum must sit
  // at the mirror point of the light in the plane, where n.h = 1.
  const Scene& s = r.scene;
  const Vec3 e = s.camera.eye, l = s.lights[0].position;
  Vec3 peak = (e * l.z + l * e.z) / (e.z + l.z);
  peak.z = 0.0f;
  const CameraFrame frame(s.camera);
  float best = -1.0f;
  Vec3 bestHit(0.0f);
  for (int y = 0; y < r.image.height(); ++y)
    for (int x = 0; x < r.image.width(); ++x) {
      const Ray ray = referenceCameraRay(s.camera, frame, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      const Vec3 hit = ray.origin + (-ray.origin.z / ray.dir.z) * ray.dir;
      const float nhp = r.image.at(x, y).g * glm::dot(l - hit, l - hit) / 3.0f;
      if (nhp > best) best = nhp, bestHit = hit;
    }
  EXPECT_LT(glm::length(bestHit - peak), 0.1f);  // within a pixel's footprint (about 0.07 there)
  EXPECT_GT(best, 0.99f);
}

TEST(A1_1_Render, CheckerboardIsPerspectiveCorrect) {
  // A checker of 16 x 16 squares over the plane, seen at a grazing angle:
  // affine interpolation of uv would bend the squares; every pixel whose
  // centre is clearly inside a square must have that square's colour, as in
  // the ray-cast image of the same scene.
  const std::string material =
      R"({"texture": {"type": "checker", "squares": [16, 16], "color_a": [1, 0, 0], "color_b": [0, 0, 1]}})";
  std::string text = planeScene(material);
  // A directional light straight down the normal: n.l = 1 and no 1/r^2, so L = kd = the square's colour.
  const std::string point = R"({"type": "point", "position": [-0.4, 0.9, 1.5], "intensity": [3, 3, 3]})";
  text.replace(text.find(point), point.size(), R"({"type": "directional", "direction": [0, 0, -1], "intensity": [1, 1, 1]})");
  const Rendered r = renderText(text, "blinn-phong", {});
  const Rendered cast = renderText(text, "raycast", {});  // the ray-cast image of the same scene
  const CameraFrame frame(r.scene.camera);
  int checked = 0;
  for (int y = 0; y < r.image.height(); ++y)
    for (int x = 0; x < r.image.width(); ++x) {
      const Ray ray = referenceCameraRay(r.scene.camera, frame, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      const Vec3 p = ray.origin + (-ray.origin.z / ray.dir.z) * ray.dir;
      if (std::abs(p.x) > 1.95f || std::abs(p.y) > 1.95f) continue;
      const Vec2 uv((p.x + 2.0f) / 4.0f * 16.0f, (p.y + 2.0f) / 4.0f * 16.0f);  // in squares
      const Vec2 frac = uv - glm::floor(uv);
      if (std::min({frac.x, frac.y, 1.0f - frac.x, 1.0f - frac.y}) < 0.02f) continue;  // on a boundary
      const bool even = (static_cast<int>(std::floor(uv.x)) + static_cast<int>(std::floor(uv.y))) % 2 == 0;
      ASSERT_EQ(r.image.at(x, y), even ? Rgb(1, 0, 0) : Rgb(0, 0, 1)) << x << "," << y;
      ASSERT_EQ(r.image.at(x, y), cast.image.at(x, y)) << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 1000);
}

TEST(A1_3_Pipeline, DepthBufferSeparatesTheLightFromTheCeilingHalfAMillimetreAbove) {
  // The Cornell box's light quad hangs 0.5 mm below the ceiling, 800 mm from
  // the camera. With the depth range fitted to the scene every pixel whose
  // pixel centre sees the light in the ray-cast image sees it here too (a
  // near plane at 1e-5 of the scene's reach lost about 9 % of them to the ceiling).
  std::string text = readTextFile(std::string(LIGHTLAB_DATA_DIR) + "/scenes/cornell_box.json");
  const Rendered r = renderText(text, "blinn-phong", {{"samples", "1"}});
  const Rendered cast = renderText(text, "raycast", {{"intersection", "framework"}});
  int light = 0, lost = 0;
  for (int y = 0; y < r.image.height(); ++y)
    for (int x = 0; x < r.image.width(); ++x) {
      if (maxComponent(cast.image.at(x, y)) < 5.0f) continue;  // not the emitter (Le ~ 17..18)
      ++light;
      if (maxComponent(r.image.at(x, y)) < 5.0f) ++lost;
    }
  EXPECT_GT(light, 500);
  EXPECT_EQ(lost, 0) << "of " << light << " light pixels";
}

TEST(A1_4_Render, AgreesWithRayCastingOnALoneSphere) {
  // Nothing can shadow anything here, so ray casting computes the same
  // local model: a finely tessellated sphere must match the exact one.
  const std::string path = std::string(LIGHTLAB_DATA_DIR) + "/scenes/tests/sphere_point_light.json";
  const Scene scene = loadScene(path);
  const auto render = [&](const std::string& name, std::vector<std::pair<std::string, std::string>> sets, int spp) {
    const AcceleratorInfo& none = findAccelerator("none");
    const auto accel = buildAccelerator(none, ParamSet(none.name, none.params), scene.geometry);
    const TechniqueInfo& info = findTechnique(name);
    ParamSet params(info.name, info.params);
    for (const auto& [k, v] : sets) params.set(k, v);
    const auto t = info.make();
    RenderSettings settings;
    settings.width = settings.height = 64;
    settings.spp = spp;
    RenderJob job(scene, *accel, *t, params, settings);
    job.run();
    return job.frame().resolve(false);
  };
  const Image raster = render("blinn-phong", {{"samples", "16"}, {"sphere_segments", "256"}}, 1);
  const Image cast = render("raycast", {{"intersection", "framework"}}, 64);
  const ImageError e = compareImages(raster, cast);
  EXPECT_GT(e.ssim, 0.98);  // metric: SSIM >= 0.98 and RMSE <= 1% of the peak value
  float peak = 0.0f;
  for (const Rgb& c : cast.pixels()) peak = std::max(peak, c.g);
  EXPECT_LT(e.rmse, 0.01 * static_cast<double>(peak));
  EXPECT_NEAR(raster.at(32, 32).r, cast.at(32, 32).r, 0.01f);
}

TEST(A1_4_Render, PhongShowsTheHighlightGouraudMissesIt) {
  // The plane is two triangles and the highlight falls inside them: lit at
  // the corners only, Gouraud interpolates four dim values and loses the peak.
  const std::string text = planeScene(R"({"ks": [1, 1, 1], "shininess": 40})");
  const auto peakOf = [&](const char* shading) {
    const Rendered r = renderText(text, "blinn-phong", {{"shading", shading}});
    float peak = 0.0f;
    for (const Rgb& c : r.image.pixels()) peak = std::max(peak, c.g);
    return peak;
  };
  EXPECT_GT(peakOf("phong"), 5.0f * peakOf("gouraud"));
}

TEST(A1_Render, SameImageWithOneAndTwoThreadsAndNoNonFinite) {
  const std::string text = planeScene(R"({"ka": [0.1, 0.1, 0.1], "kd": [0.7, 0.5, 0.3], "ks": [0.5, 0.5, 0.5], "shininess": 20})");
  Rendered one, two;
  {
    const tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = renderText(text, "blinn-phong", {{"samples", "4"}});
  }
  {
    const tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    two = renderText(text, "blinn-phong", {{"samples", "4"}});
  }
  EXPECT_EQ(one.image.pixels(), two.image.pixels());
  EXPECT_EQ(one.stats.work.nonFinite, 0u);
}

}  // namespace
}  // namespace ll
