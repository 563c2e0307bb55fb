// Assignment 3 tests: the tasks on closed-form answers (mirror direction,
// Snell, the Fresnel equations, the critical and Brewster angles), whole ray
// trees on small scenes (45-degree mirror, lateral shift through a slab,
// Beer-Lambert, nested dielectrics, coordinates around 1e5), and the
// technique against ray casting where both must agree.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "a3_tasks.h"
#include "modules/registry.h"
#include "render/render_job.h"
#include "scene/scene_loader.h"
#include "test_support.h"
#include "whitted_tracer.h"

namespace ll {
namespace {

using testing_support::implemented;

constexpr float kDeg = kPi / 180.0f;

// --- A3.1 reflection ------------------------------------------------------------

TEST(A3_1_Reflect, MirrorDirectionKeepsTheTangentAndFlipsTheNormalPart) {
  Vec3 r;
  ASSERT_TRUE(implemented("A3.1", [&] { r = a3::reflect(Vec3(0, 0, -1), glm::normalize(Vec3(1, 0, 1))); }));
  EXPECT_NEAR(r.x, 1.0f, 1e-6f);  // 45 degrees: straight down the x axis
  EXPECT_NEAR(r.y, 0.0f, 1e-6f);
  EXPECT_NEAR(r.z, 0.0f, 1e-6f);
  const Vec3 d = glm::normalize(Vec3(0.3f, -0.8f, 0.2f)), n(0, 1, 0);
  const Vec3 q = a3::reflect(d, n);
  EXPECT_NEAR(q.x, d.x, 1e-6f);
  EXPECT_NEAR(q.y, -d.y, 1e-6f);
  EXPECT_NEAR(q.z, d.z, 1e-6f);
  const Vec3 back = a3::reflect(d, -n);  // either side of the normal
  EXPECT_NEAR(glm::length(back - q), 0.0f, 1e-6f);
}

// --- A3.2 refraction --------------------------------------------------------------

TEST(A3_2_Refract, SnellsLawHolds) {
  for (float deg : {0.0f, 10.0f, 30.0f, 60.0f, 89.0f}) {
    const float i = deg * kDeg;
    const Vec3 d(std::sin(i), -std::cos(i), 0.0f), n(0, 1, 0);
    Vec3 t(0.0f);
    bool ok = false;
    ASSERT_TRUE(implemented("A3.2", [&] { ok = a3::refract(d, n, 1.0f / 1.5f, t); }));
    ASSERT_TRUE(ok) << deg;
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
    EXPECT_NEAR(1.0f * std::sin(i), 1.5f * t.x, 1e-5f) << deg;  // n1 sin(theta_i) = n2 sin(theta_t)
    EXPECT_LT(t.y, 0.0f);  // goes on through the surface
    EXPECT_NEAR(t.z, 0.0f, 1e-6f);  // in the plane of incidence
  }
}

TEST(A3_2_Refract, CriticalAngleOfGlassIs41_81Degrees) {
  const float critical = std::asin(1.0f / 1.5f) / kDeg;
  EXPECT_NEAR(critical, 41.81f, 0.005f);
  const auto inside = [](float deg) {  // from glass (1.5) into air (1.0)
    Vec3 t(0.0f);
    return a3::refract(Vec3(std::sin(deg * kDeg), -std::cos(deg * kDeg), 0.0f), Vec3(0, 1, 0), 1.5f, t);
  };
  EXPECT_TRUE(inside(41.7f));   // just below: refraction exists (grazing)
  EXPECT_FALSE(inside(41.9f));  // just above: total internal reflection
  EXPECT_FALSE(inside(80.0f));
  Vec3 t(0.0f);
  ASSERT_TRUE(a3::refract(Vec3(std::sin(41.8f * kDeg), -std::cos(41.8f * kDeg), 0.0f), Vec3(0, 1, 0), 1.5f, t));
  EXPECT_GT(t.x, 0.999f);  // at the critical angle the refracted ray skims the surface
}

// --- A3.3 Fresnel -------------------------------------------------------------------

// The transmittances from the amplitude coefficients t_s, t_p (Hecht, Optics,
// ch. 4): T = (n2 cos_t)/(n1 cos_i) t^2. Independent of A3.3's reflectances.
void transmittances(float cosI, float n1, float n2, float& ts2, float& tp2) {
  const float sinT = n1 / n2 * std::sqrt(1.0f - cosI * cosI);
  const float cosT = std::sqrt(1.0f - sinT * sinT);
  const float ts = 2.0f * n1 * cosI / (n1 * cosI + n2 * cosT);
  const float tp = 2.0f * n1 * cosI / (n2 * cosI + n1 * cosT);
  const float factor = (n2 * cosT) / (n1 * cosI);
  ts2 = factor * ts * ts;
  tp2 = factor * tp * tp;
}

TEST(A3_3_Fresnel, ReflectedPlusTransmittedIsOneAtEveryAngle) {
  for (const auto& indices : {std::pair{1.0f, 1.5f}, std::pair{1.5f, 1.0f}, std::pair{1.33f, 1.5f}}) {
    const float n1 = indices.first, n2 = indices.second;  // not a structured binding: Clang 14 cannot capture those
    for (float deg = 0.0f; deg < 89.5f; deg += 2.5f) {
      const float cosI = std::cos(deg * kDeg);
      if ((n1 / n2) * std::sin(deg * kDeg) >= 1.0f) break;  // beyond the critical angle
      a3::FresnelTerms f;
      ASSERT_TRUE(implemented("A3.3", [&] { f = a3::fresnelDielectric(cosI, n1, n2); }));
      float ts2 = 0, tp2 = 0;
      transmittances(cosI, n1, n2, ts2, tp2);
      EXPECT_NEAR(f.rs + ts2, 1.0f, 1e-4f) << n1 << "->" << n2 << " at " << deg;
      EXPECT_NEAR(f.rp + tp2, 1.0f, 1e-4f) << n1 << "->" << n2 << " at " << deg;
    }
  }
}

TEST(A3_3_Fresnel, NormalIncidenceBrewsterAndTotalInternalReflection) {
  EXPECT_NEAR(a3::fresnelDielectric(1.0f, 1.0f, 1.5f).unpolarized(), 0.04f, 1e-6f);  // ((n-1)/(n+1))^2
  EXPECT_NEAR(a3::fresnelDielectric(1.0f, 1.5f, 1.0f).unpolarized(), 0.04f, 1e-6f);  // the same from inside
  const float brewster = std::atan(1.5f);  // tan(theta_B) = n2 / n1
  const a3::FresnelTerms b = a3::fresnelDielectric(std::cos(brewster), 1.0f, 1.5f);
  EXPECT_NEAR(b.rp, 0.0f, 1e-6f);  // p-polarised light is not reflected at all
  EXPECT_GT(b.rs, 0.1f);
  const a3::FresnelTerms grazing = a3::fresnelDielectric(std::cos(89.99f * kDeg), 1.0f, 1.5f);
  EXPECT_GT(grazing.unpolarized(), 0.99f);  // everything is reflected at grazing incidence
  const a3::FresnelTerms tir = a3::fresnelDielectric(std::cos(45.0f * kDeg), 1.5f, 1.0f);
  EXPECT_EQ(tir.rs, 1.0f);
  EXPECT_EQ(tir.rp, 1.0f);
}

TEST(A3_3_Fresnel, SchlicksApproximationIsCloseButNotExact) {
  float worst = 0.0f;
  for (float deg = 0.0f; deg < 90.0f; deg += 1.0f) {
    const float c = std::cos(deg * kDeg);
    worst = std::max(worst, std::abs(a3::fresnelSchlick(c, 1.0f, 1.5f) - a3::fresnelDielectric(c, 1.0f, 1.5f).unpolarized()));
  }
  EXPECT_NEAR(a3::fresnelSchlick(1.0f, 1.0f, 1.5f), 0.04f, 1e-6f);
  EXPECT_GT(worst, 1e-3f);
  EXPECT_LT(worst, 0.05f);
  EXPECT_EQ(a3::fresnelSchlick(std::cos(45.0f * kDeg), 1.5f, 1.0f), 1.0f);  // total internal reflection
}

// --- A3.5 secondary-ray origins -----------------------------------------------------

TEST(A3_5_SecondaryRay, OffsetScalesWithTheMagnitudeOfThePoint) {
  for (float scale : {1.0f, 1e3f, 1e5f}) {
    const Vec3 p(scale, 0.5f * scale, -scale);
    Ray r;
    ASSERT_TRUE(implemented("A3.5", [&] { r = a3::secondaryRay(p, Vec3(0, 1, 0), glm::normalize(Vec3(1, 1, 0))); }));
    EXPECT_GT(r.origin.y, p.y) << scale;  // off the plane y = p.y, on the side the ray leaves to
    EXPECT_LT(r.origin.y - p.y, 1e-3f * scale) << scale;  // by a relative amount, not a fixed one
    EXPECT_EQ(r.tmin, 0.0f);
    const Ray under = a3::secondaryRay(p, Vec3(0, 1, 0), glm::normalize(Vec3(1, -1, 0)));
    EXPECT_LT(under.origin.y, p.y) << scale;
  }
}

// --- whole ray trees -----------------------------------------------------------------

Scene sceneFrom(const std::string& text) {
  return parseJsonScene(text, "test.json", std::string(LIGHTLAB_DATA_DIR) + "/scenes");
}

// The ray tree of the sample through the centre of pixel (x, y).
RayTree treeAt(const Scene& scene, int x, int y, std::vector<std::pair<std::string, std::string>> sets = {}) {
  const AcceleratorInfo& a = findAccelerator("bvh");
  const auto accel = buildAccelerator(a, ParamSet(a.name, a.params), scene.geometry);
  const TechniqueInfo& info = findTechnique("whitted");
  ParamSet params(info.name, info.params);
  for (const auto& [k, v] : sets) params.set(k, v);
  RenderSettings settings;
  settings.width = scene.camera.width;
  settings.height = scene.camera.height;
  const RenderContext ctx{scene, *accel, params, settings, nullptr};
  const auto technique = info.make();
  technique->prepare(ctx);
  auto tree = technique->rayTree(ctx, Vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
  EXPECT_TRUE(tree.has_value());
  return tree.value_or(RayTree{});
}

// The first child of node `parent` of the given kind, or -1.
int child(const RayTree& tree, int parent, RayKind kind) {
  for (size_t i = 0; i < tree.nodes.size(); ++i)
    if (tree.nodes[i].parent == parent && tree.nodes[i].kind == kind) return static_cast<int>(i);
  return -1;
}

struct Rendered {
  Image image;
  RenderStats stats;
};

Rendered render(const Scene& scene, const std::string& technique, std::vector<std::pair<std::string, std::string>> sets,
                int width, int height) {
  const AcceleratorInfo& a = findAccelerator("bvh");
  const auto accel = buildAccelerator(a, ParamSet(a.name, a.params), scene.geometry);
  const TechniqueInfo& info = findTechnique(technique);
  ParamSet params(info.name, info.params);
  for (const auto& [k, v] : sets) params.set(k, v);
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  const auto t = info.make();
  RenderJob job(scene, *accel, *t, params, settings);
  job.run();
  return {job.frame().resolve(false), job.stats()};
}

uint64_t rays(const RenderStats& s, RayKind kind) { return s.work.rays[static_cast<size_t>(kind)]; }

// A mirror at 45 degrees to the camera ray, a target sphere where the mirror sends the ray.
std::string mirrorScene(const std::string& offset) {
  return R"({
    "camera": {"eye": [)" + offset + R"(, 5], "target": [)" + offset + R"(, 0], "up": [0, 1, 0], "fov_y_deg": 20, "width": 33, "height": 33},
    "background": [0, 0, 0],
    "materials": {"mirror": {"mirror": [0.9, 0.9, 0.9]}, "red": {"kd": [0.8, 0.1, 0.1]}},
    "lights": [{"type": "point", "position": [0, 5, 5], "intensity": [20, 20, 20]}],
    "objects": [
      {"type": "quad", "name": "mirror", "material": "mirror", "transform": {"translate": [)" + offset + R"(, 0]},
       "vertices": [[-0.7071, -1, -0.7071], [0.7071, -1, 0.7071], [0.7071, 1, 0.7071], [-0.7071, 1, -0.7071]]},
      {"type": "sphere", "name": "target", "material": "red", "center": [-3, 0, 0], "radius": 0.5,
       "transform": {"translate": [)" + offset + R"(, 0]}}
    ]
  })";
}

TEST(A3_1_Whitted, MirrorAt45DegreesSendsTheRayToTheTarget) {
  const Scene scene = sceneFrom(mirrorScene("0, 0"));
  const RayTree tree = treeAt(scene, 16, 16);
  ASSERT_GE(tree.nodes.size(), 2u);
  EXPECT_EQ(tree.nodes[0].object, "mirror");
  const int r = child(tree, 0, RayKind::Reflection);
  ASSERT_GE(r, 0);
  const RayTreeNode& n = tree.nodes[static_cast<size_t>(r)];
  EXPECT_NEAR(n.direction.x, -1.0f, 1e-5f);
  EXPECT_NEAR(n.direction.z, 0.0f, 1e-5f);
  EXPECT_TRUE(n.hit);
  EXPECT_EQ(n.object, "target");
  EXPECT_NEAR(n.t, 2.5f, 1e-4f);  // from the mirror's centre to the sphere's near side
  EXPECT_NEAR(n.throughput.r, 0.9f, 1e-6f);
  // Only the rays the scene calls for: nothing transmits here.
  const Rendered img = render(scene, "whitted", {}, 33, 33);
  EXPECT_GT(rays(img.stats, RayKind::Reflection), 0u);
  EXPECT_EQ(rays(img.stats, RayKind::Refraction), 0u);
}

// A glass slab between z = 0 and z = -thickness (front and back faces wound outwards).
std::string slabScene(const std::string& camera, const std::string& glass, float thickness) {
  const std::string back = std::to_string(-thickness);
  return R"({
    "camera": )" + camera + R"(,
    "background": [1, 1, 1],
    "materials": {"glass": )" + glass + R"(},
    "objects": [
      {"type": "quad", "name": "front", "material": "glass", "vertices": [[-50, -50, 0], [50, -50, 0], [50, 50, 0], [-50, 50, 0]]},
      {"type": "quad", "name": "back", "material": "glass",
       "vertices": [[-50, -50, )" + back + R"(], [-50, 50, )" + back + R"(], [50, 50, )" + back + R"(], [50, -50, )" + back + R"(]]}
    ]
  })";
}

TEST(A3_2_Whitted, GlassSlabShiftsARayByTheClosedFormAmount) {
  const float theta = 30.0f * kDeg, h = 1.0f;
  const Vec3 d(std::sin(theta), 0.0f, -std::cos(theta));
  const Vec3 eye = -5.0f * d;
  const std::string camera = "{\"eye\": [" + std::to_string(eye.x) + ", 0, " + std::to_string(eye.z) +
                             "], \"target\": [0, 0, 0], \"up\": [0, 1, 0], \"fov_y_deg\": 10, \"width\": 33, \"height\": 33}";
  const Scene scene = sceneFrom(slabScene(camera, R"({"transmission": [1, 1, 1], "ior": 1.5})", h));
  const RayTree tree = treeAt(scene, 16, 16);
  const int in = child(tree, 0, RayKind::Refraction);
  ASSERT_GE(in, 0);
  EXPECT_EQ(tree.nodes[static_cast<size_t>(in)].object, "back");
  const int out = child(tree, in, RayKind::Refraction);
  ASSERT_GE(out, 0);
  const RayTreeNode& exit = tree.nodes[static_cast<size_t>(out)];
  EXPECT_NEAR(glm::length(exit.direction - d), 0.0f, 1e-5f);  // leaves parallel to how it came in
  const float thetaT = std::asin(std::sin(theta) / 1.5f);
  const float shift = h * std::sin(theta - thetaT) / std::cos(thetaT);  // 0.1938 for 30 degrees
  const Vec3 c = tree.nodes[0].origin;
  const float distance = glm::length(glm::cross(exit.origin - c, glm::normalize(tree.nodes[0].direction)));
  EXPECT_NEAR(distance, shift, 2e-4f);
  EXPECT_NEAR(shift, 0.1938f, 1e-4f);
}

TEST(A3_4_Whitted, BeerLambertAttenuatesByExpMinusSigmaTimesDistance) {
  const std::string camera =
      R"({"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 10, "width": 33, "height": 33})";
  const Scene scene =
      sceneFrom(slabScene(camera, R"({"transmission": [1, 1, 1], "ior": 1.5, "absorption": [0.5, 1, 2]})", 2.0f));
  const RayTree tree = treeAt(scene, 16, 16);
  const int in = child(tree, 0, RayKind::Refraction);
  ASSERT_GE(in, 0);
  const int out = child(tree, in, RayKind::Refraction);
  ASSERT_GE(out, 0);
  // Normal incidence: F = 0.04 at both faces, and 2 units of glass in between.
  const RayTreeNode& exit = tree.nodes[static_cast<size_t>(out)];
  const Vec3 expected = 0.96f * 0.96f * glm::exp(-2.0f * Vec3(0.5f, 1.0f, 2.0f));
  EXPECT_NEAR(exit.throughput.r, expected.r, 1e-5f);
  EXPECT_NEAR(exit.throughput.g, expected.g, 1e-5f);
  EXPECT_NEAR(exit.throughput.b, expected.b, 1e-5f);
  EXPECT_NEAR(tree.nodes[static_cast<size_t>(in)].absorption.b, std::exp(-4.0f), 1e-6f);
}

TEST(A3_2_Whitted, NestedDielectricsUseTheRelativeIndexAtEachInterface) {
  // A glass sphere (1.5) inside a water sphere (1.33), the camera ray through both centres.
  const Scene scene = sceneFrom(R"({
    "camera": {"eye": [0, 0, 10], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 10, "width": 33, "height": 33},
    "background": [1, 1, 1],
    "materials": {"water": {"transmission": [1, 1, 1], "ior": 1.33}, "glass": {"transmission": [1, 1, 1], "ior": 1.5}},
    "objects": [
      {"type": "sphere", "name": "water", "material": "water", "center": [0, 0, 0], "radius": 2},
      {"type": "sphere", "name": "glass", "material": "glass", "center": [0, 0, 0], "radius": 1}
    ]
  })");
  const RayTree tree = treeAt(scene, 16, 16);
  struct Expect {
    const char* object;
    bool entering;
    float n1, n2;
  };
  const Expect path[] = {{"water", true, 1.0f, 1.33f},
                         {"glass", true, 1.33f, 1.5f},
                         {"glass", false, 1.5f, 1.33f},
                         {"water", false, 1.33f, 1.0f}};
  int node = 0;
  for (const Expect& e : path) {
    ASSERT_GE(node, 0);
    const RayTreeNode& n = tree.nodes[static_cast<size_t>(node)];
    EXPECT_EQ(n.object, e.object);
    EXPECT_EQ(n.entering, e.entering) << e.object;
    EXPECT_FLOAT_EQ(n.n1, e.n1) << e.object;
    EXPECT_FLOAT_EQ(n.n2, e.n2) << e.object;
    node = child(tree, node, RayKind::Refraction);
  }
  ASSERT_GE(node, 0);
  EXPECT_FALSE(tree.nodes[static_cast<size_t>(node)].hit);  // out into the background
}

// The six faces of an axis-aligned box as quads wound outwards (JSON objects, comma-separated).
std::string boxQuads(const std::string& name, const std::string& material, Vec3 lo, Vec3 hi) {
  std::string out;
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;  // e_b x e_c = e_a
      Vec3 v[4];
      for (int k = 0; k < 4; ++k) {
        v[k][a] = side ? hi[a] : lo[a];
        v[k][b] = (k == 1 || k == 2) ? hi[b] : lo[b];
        v[k][c] = (k >= 2) ? hi[c] : lo[c];
      }
      if (!side) std::swap(v[1], v[3]);  // the low face looks the other way
      std::string verts;
      for (int k = 0; k < 4; ++k)
        verts += (k ? ", [" : "[") + std::to_string(v[k].x) + ", " + std::to_string(v[k].y) + ", " +
                 std::to_string(v[k].z) + "]";
      out += std::string(out.empty() ? "" : ", ") + R"({"type": "quad", "name": ")" + name + R"(", "material": ")" +
             material + R"(", "vertices": [)" + verts + "]}";
    }
  return out;
}

TEST(A3_2_Whitted, TotalInternalReflectionInsideAGlassBlockSpawnsNoRefractionRay) {
  // Looking into a glass cube's face at 60 degrees: inside, the ray meets the side face at 90 - 35.3 = 54.7
  // degrees, above the critical 41.8: it must reflect totally.
  const float theta = 60.0f * kDeg;
  const Vec3 d(std::sin(theta), 0.0f, -std::cos(theta));
  const Vec3 eye = Vec3(-1.0f, 0.0f, 0.0f) - 5.0f * d;  // aimed at (-1, 0, 0) on the top face z = 0
  const Scene scene = sceneFrom(R"({
    "camera": {"eye": [)" + std::to_string(eye.x) + ", 0, " + std::to_string(eye.z) +
                                R"(], "target": [-1, 0, 0], "up": [0, 1, 0], "fov_y_deg": 5, "width": 33, "height": 33},
    "background": [1, 1, 1],
    "materials": {"glass": {"transmission": [1, 1, 1], "ior": 1.5}},
    "objects": [)" + boxQuads("block", "glass", Vec3(-2, -2, -4), Vec3(0.5f, 2, 0)) +
                                R"(]
  })");
  const RayTree tree = treeAt(scene, 16, 16);
  const int in = child(tree, 0, RayKind::Refraction);
  ASSERT_GE(in, 0);
  const RayTreeNode& side = tree.nodes[static_cast<size_t>(in)];
  ASSERT_TRUE(side.hit);
  EXPECT_NEAR(side.position.x, 0.5f, 1e-4f);  // the side face x = 0.5
  EXPECT_TRUE(side.totalInternalReflection);
  EXPECT_EQ(child(tree, in, RayKind::Refraction), -1);
  const int reflected = child(tree, in, RayKind::Reflection);
  ASSERT_GE(reflected, 0);
  EXPECT_NEAR(tree.nodes[static_cast<size_t>(reflected)].throughput.r, tree.nodes[static_cast<size_t>(in)].throughput.r,
              1e-6f);  // all of it
}

TEST(A3_5_Whitted, FarFromTheOriginNoSecondaryRayReHitsItsOwnSurface) {
  for (const char* offset : {"0, 0", "100000, 100000"}) {
    const Scene scene = sceneFrom(mirrorScene(offset));
    int mirrorHits = 0;
    for (int y = 2; y < 33; y += 3)
      for (int x = 2; x < 33; x += 3) {
        const RayTree tree = treeAt(scene, x, y);
        if (tree.nodes.empty() || tree.nodes[0].object != "mirror") continue;
        ++mirrorHits;
        for (const RayTreeNode& n : tree.nodes) {
          if (n.kind != RayKind::Camera) {
            EXPECT_NE(n.object, "mirror") << offset << " pixel " << x << "," << y;
          }
        }
      }
    EXPECT_GT(mirrorHits, 20) << offset;
  }
}

TEST(A3_Whitted, DiffuseOnlySceneRendersAsRayCastingWithNoReflectionOrRefractionRays) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/cornell_box.json");
  const Rendered w = render(scene, "whitted", {}, 48, 48);
  const Rendered r = render(scene, "raycast", {{"intersection", "framework"}}, 48, 48);
  EXPECT_EQ(rays(w.stats, RayKind::Reflection), 0u);
  EXPECT_EQ(rays(w.stats, RayKind::Refraction), 0u);
  EXPECT_EQ(rays(w.stats, RayKind::Shadow), rays(r.stats, RayKind::Shadow));
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(w.image.at(x, y)[c], r.image.at(x, y)[c], 1e-5f * (1.0f + r.image.at(x, y)[c])) << x << "," << y;
}

TEST(A3_Whitted, NoShadowRaysWhereNothingCanCastAShadow) {
  // One convex sphere and a point light: no surface can stand between a point and the light.
  const Scene lone = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/tests/sphere_point_light.json");
  const Rendered r = render(lone, "whitted", {}, 32, 32);
  EXPECT_EQ(rays(r.stats, RayKind::Shadow), 0u);
  EXPECT_EQ(rays(r.stats, RayKind::Reflection) + rays(r.stats, RayKind::Refraction), 0u);
  EXPECT_EQ(rays(r.stats, RayKind::Camera), 32u * 32u);
  const Scene shadowed = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/tests/shadow_quad.json");
  EXPECT_GT(rays(render(shadowed, "whitted", {}, 32, 32).stats, RayKind::Shadow), 0u);
}

TEST(A3_Whitted, ShadowRaysOnlyForTheLightsSomethingCanOcclude) {
  // Two spheres far apart: light A between them lights each without anything in between; light B beyond
  // the right sphere can be blocked by it on its way to the left one.
  const auto scene = [](const std::string& lights) {
    return parseJsonScene(R"({"camera": {"eye": [0, 0, 12], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 40,
      "width": 32, "height": 32}, "materials": {"grey": {"kd": [0.5, 0.5, 0.5]}},
      "lights": [)" + lights + R"(], "objects": [
      {"type": "sphere", "material": "grey", "center": [-2, 0, 0], "radius": 0.5},
      {"type": "sphere", "material": "grey", "center": [2, 0, 0], "radius": 0.5}]})",
                          "test.json", std::string(LIGHTLAB_DATA_DIR) + "/scenes");
  };
  const std::string a = R"({"type": "point", "position": [0, 0, 0], "intensity": [5, 5, 5]})";
  const std::string b = R"({"type": "point", "position": [6, 0, 0], "intensity": [5, 5, 5]})";
  const Scene onlyA = scene(a), onlyB = scene(b), both = scene(a + ", " + b);
  EXPECT_FALSE(onlyA.lights[0].canBeOccluded);
  EXPECT_TRUE(onlyB.lights[0].canBeOccluded);
  EXPECT_FALSE(onlyA.effects.has(Effect::HardShadows));
  EXPECT_TRUE(both.effects.has(Effect::HardShadows));
  const Rendered ra = render(onlyA, "whitted", {}, 32, 32), rb = render(onlyB, "whitted", {}, 32, 32);
  const Rendered rab = render(both, "whitted", {}, 32, 32);
  EXPECT_EQ(rays(ra.stats, RayKind::Shadow), 0u);
  EXPECT_GT(rays(rb.stats, RayKind::Shadow), 0u);
  EXPECT_EQ(rays(rab.stats, RayKind::Shadow), rays(rb.stats, RayKind::Shadow));  // none for A
  const Rendered cast = render(both, "raycast", {{"intersection", "framework"}}, 32, 32);
  EXPECT_EQ(rays(cast.stats, RayKind::Shadow), rays(rb.stats, RayKind::Shadow));
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(rab.image.at(x, y)[c], ra.image.at(x, y)[c] + rb.image.at(x, y)[c], 1e-5f) << x << "," << y;
}

TEST(A3_4_Whitted, DepthZeroIsRayCastingAndDeeperAddsReflections) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/whitted_1980.json");
  const Rendered flat = render(scene, "whitted", {{"max_depth", "0"}}, 64, 48);
  const Rendered deep = render(scene, "whitted", {}, 64, 48);
  EXPECT_EQ(rays(flat.stats, RayKind::Reflection) + rays(flat.stats, RayKind::Refraction), 0u);
  EXPECT_GT(rays(deep.stats, RayKind::Reflection), 0u);
  EXPECT_GT(rays(deep.stats, RayKind::Refraction), 0u);
  EXPECT_EQ(deep.stats.work.nonFinite, 0u);
  // The throughput threshold prunes: a high one traces fewer rays.
  const Rendered pruned = render(scene, "whitted", {{"min_throughput", "0.2"}}, 64, 48);
  EXPECT_LT(pruned.stats.work.totalRays(), deep.stats.work.totalRays());
}

TEST(A3_4_Whitted, TreeContributionsSumToThePixel) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/whitted_1980.json");
  for (const auto& [x, y] : {std::pair{380, 200}, std::pair{250, 200}, std::pair{100, 400}}) {
    const RayTree tree = treeAt(scene, x, y);
    // These pixels see the spheres: a camera ray, its shadow rays and at least one reflected or refracted ray.
    ASSERT_GE(tree.nodes.size(), 3u) << x << "," << y << ": the ray tree has no children";
    ASSERT_GT(maxComponent(tree.pixel), 0.0f) << x << "," << y;
    Rgb sum(0.0f);
    bool background = false;
    for (const RayTreeNode& n : tree.nodes) {
      sum += n.contribution;
      if (n.intersected && !n.hit && n.kind != RayKind::Shadow) background = true;
    }
    // Misses add the background, which no node's local term holds: add those leaves' weighted radiance.
    for (const RayTreeNode& n : tree.nodes)
      if (n.intersected && !n.hit && n.kind != RayKind::Shadow) sum += n.throughput * n.radiance;
    (void)background;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], tree.pixel[c], 1e-4f * (1.0f + tree.pixel[c])) << x << "," << y;
  }
}

}  // namespace
}  // namespace ll
