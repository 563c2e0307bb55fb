// Light-path classes (render/light_path_class.h): the classes of `path` add
// up to its picture on every bundled scene, a class that cannot occur stays
// exactly zero, leaving classes out (effects=measured) removes exactly those
// classes, and the probe's relMSE-without estimate agrees with a converged
// render.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "metrics/image_metrics.h"
#include "modules/registry.h"
#include "render_support.h"
#include "render/light_path_probe.h"
#include "render/render_job.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {


// --- The state machine: each event sequence lands in the class Heckbert's notation gives it ----------------

LightPathClass classOf(std::initializer_list<PathVertex> fromEye) {
  LightPathState s;
  for (PathVertex v : fromEye) s = s.then(v);
  return s.atLight();
}

constexpr PathVertex D = PathVertex::Diffuse, G = PathVertex::Glossy, R = PathVertex::SpecularReflection,
                     T = PathVertex::SpecularRefraction;

TEST(LightPathState, EventSequencesLandInTheirClass) {
  EXPECT_EQ(classOf({}), LightPathClass::Emission);                       // L E
  EXPECT_EQ(classOf({D}), LightPathClass::DirectLighting);                // L D E
  EXPECT_EQ(classOf({G}), LightPathClass::DirectLighting);                // a rough metal lit directly
  EXPECT_EQ(classOf({R}), LightPathClass::MirrorReflection);              // L S E: the light in a mirror
  EXPECT_EQ(classOf({R, D}), LightPathClass::MirrorReflection);           // L D S E: a lit wall in a mirror
  EXPECT_EQ(classOf({R, T, T, D}), LightPathClass::Refraction);           // through glass seen in a mirror
  EXPECT_EQ(classOf({T, T}), LightPathClass::Refraction);                 // L S S E: the light through glass
  EXPECT_EQ(classOf({D, D}), LightPathClass::DiffuseInterreflection);     // L D D E
  EXPECT_EQ(classOf({D, G, D}), LightPathClass::DiffuseInterreflection);  // the first bounce from the eye is D
  EXPECT_EQ(classOf({G, D}), LightPathClass::GlossyReflection);           // L D G E: a wall in a rough metal
  EXPECT_EQ(classOf({R, G, D}), LightPathClass::GlossyReflection);        // ... seen in a mirror
  EXPECT_EQ(classOf({D, T, T}), LightPathClass::Caustics);                // L S S D E: light through glass
  EXPECT_EQ(classOf({D, R}), LightPathClass::Caustics);                   // L S D E
  EXPECT_EQ(classOf({D, D, R}), LightPathClass::Caustics);                // a caustic lights a wall
  EXPECT_EQ(classOf({G, R}), LightPathClass::Caustics);                   // L S G E
  // The sky lighting a surface, whatever lies between; the sky seen directly or in a mirror is emission or S.
  LightPathState s;
  EXPECT_EQ(s.atLight(true), LightPathClass::Emission);
  EXPECT_EQ(s.then(R).atLight(true), LightPathClass::MirrorReflection);
  EXPECT_EQ(s.then(D).atLight(true), LightPathClass::SkyLight);
  EXPECT_EQ(s.then(D).then(T).atLight(true), LightPathClass::SkyLight);
  EXPECT_EQ(s.then(T).then(G).then(D).atLight(true), LightPathClass::SkyLight);
}

TEST(LightPathState, ReachableClassesShrinkAlongThePath) {
  EXPECT_EQ(LightPathState{}.reachable(), kAllLightPathClasses);
  const LightPathState d = LightPathState{}.then(D);
  const LightPathMask sky = lightPathBit(LightPathClass::SkyLight);
  EXPECT_EQ(d.reachable(), lightPathBit(LightPathClass::DirectLighting) |
                               lightPathBit(LightPathClass::DiffuseInterreflection) |
                               lightPathBit(LightPathClass::Caustics) | sky);
  EXPECT_EQ(d.then(D).reachable(),
            lightPathBit(LightPathClass::DiffuseInterreflection) | lightPathBit(LightPathClass::Caustics) | sky);
  EXPECT_EQ(d.then(R).reachable(), lightPathBit(LightPathClass::Caustics) | sky);
  const LightPathState t = LightPathState{}.then(T);
  EXPECT_FALSE(t.reachable() & lightPathBit(LightPathClass::MirrorReflection));  // refracted already
  EXPECT_FALSE(t.reachable() & lightPathBit(LightPathClass::DirectLighting));
}

TEST(LightPathState, ClassesAreTheEffectsOfTheSameName) {
  for (int c = 0; c < kLightPathClassCount; ++c)
    EXPECT_STREQ(lightPathClassName(lightPathClassAt(c)), effectName(lightPathClassEffect(lightPathClassAt(c))));
}

// --- Renders -----------------------------------------------------------------------------------------------

struct SplitRender {
  Image picture;
  std::vector<Image> classes;
  RenderStats stats;
};

using Sets = std::vector<std::pair<std::string, std::string>>;

SplitRender renderSplit(const std::string& techniqueName, const Scene& scene, const Sets& sets, int width, int height,
                        int spp, uint64_t seed, bool split) {
  const AcceleratorInfo& a = findAccelerator("bvh");
  const auto accel = buildAccelerator(a, ParamSet(a.name, a.params), scene.geometry);
  const TechniqueInfo& t = findTechnique(techniqueName);
  ParamSet params(t.name, t.params);
  for (const auto& [k, v] : sets) params.set(k, v);
  const auto technique = t.make();
  RenderSettings rs = testing_support::renderSettings(width, height, spp, seed);
  rs.lightPaths = split;
  RenderJob job(scene, *accel, *technique, params, rs);
  job.run();
  SplitRender r{job.frame().resolve(false), {}, job.stats()};
  if (split && job.frame().keepsLightPaths())
    for (int c = 0; c < kLightPathClassCount; ++c) r.classes.push_back(job.frame().resolveLightPath(lightPathClassAt(c)));
  return r;
}

SplitRender renderPath(const Scene& scene, const Sets& sets, int width, int height, int spp, uint64_t seed,
                       bool split) {
  return renderSplit("path", scene, sets, width, height, spp, seed, split);
}

using testing_support::bundledScenes;

// Same seed, same streams: the split render's picture is the unsplit render's, and the classes sum to it (up to
// float rounding of the order of the sums: 1e-5 of the pixel).
TEST(LightPathClasses, AddUpToThePathImageOnEveryBundledScene) {
  const auto scenes = bundledScenes();
  ASSERT_GE(scenes.size(), 8u);
  for (const std::string& path : scenes) {
    const Scene scene = loadScene(path);
    std::vector<std::pair<std::string, std::string>> sets;
    if (scene.effects.has(Effect::Dispersion)) sets.emplace_back("spectral", "true");
    const SplitRender split = renderPath(scene, sets, 32, 24, 4, 11, true);
    const SplitRender plain = renderPath(scene, sets, 32, 24, 4, 11, false);
    ASSERT_EQ(split.classes.size(), static_cast<size_t>(kLightPathClassCount)) << path;
    double worst = 0.0, total = 0.0;
    for (size_t i = 0; i < split.picture.pixels().size(); ++i)
      for (int ch = 0; ch < 3; ++ch) {
        const double p = split.picture.pixels()[i][ch];
        EXPECT_EQ(p, static_cast<double>(plain.picture.pixels()[i][ch])) << path << " pixel " << i;
        double sum = 0.0;
        for (const Image& c : split.classes) sum += static_cast<double>(c.pixels()[i][ch]);
        worst = std::max(worst, std::abs(sum - p) / (std::abs(p) + 1e-3));
        total += p;
      }
    EXPECT_LT(worst, 1e-5) << path;
    EXPECT_GT(total, 0.0) << path;
    // The shares in the stats are those of the class images.
    ASSERT_EQ(split.stats.lightPaths.size(), static_cast<size_t>(kLightPathClassCount)) << path;
    double shares = 0.0;
    for (const LightPathShare& s : split.stats.lightPaths) shares += s.luminanceShare;
    EXPECT_NEAR(shares, 1.0, 1e-5) << path;
  }
}

bool allZero(const Image& image) {
  for (const Rgb& p : image.pixels())
    if (p.r != 0.0f || p.g != 0.0f || p.b != 0.0f) return false;
  return true;
}

// The Cornell box has no mirror, glass, rough metal or sky: no path of those classes exists.
TEST(LightPathClasses, ASceneWithoutSpecularSurfacesHasNoSpecularClasses) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/cornell_box.json");
  const SplitRender r = renderPath(scene, {}, 32, 32, 16, 3, true);
  for (LightPathClass c : {LightPathClass::MirrorReflection, LightPathClass::Refraction,
                           LightPathClass::GlossyReflection, LightPathClass::Caustics, LightPathClass::SkyLight})
    EXPECT_TRUE(allZero(r.classes[static_cast<size_t>(c)])) << lightPathClassName(c);
  for (LightPathClass c :
       {LightPathClass::Emission, LightPathClass::DirectLighting, LightPathClass::DiffuseInterreflection})
    EXPECT_FALSE(allZero(r.classes[static_cast<size_t>(c)])) << lightPathClassName(c);
}

// A mirror sphere and a glass sphere under an area light and a sky, nothing diffuse: every path is L S* E,
// and the sky lights no surface.
TEST(LightPathClasses, ASceneWithoutDiffuseSurfacesHasOnlyEmissionAndSpecularClasses) {
  const Scene scene = parseJsonScene(R"({
    "camera": {"eye": [0, 1, 6], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 40, "width": 32, "height": 24},
    "background": [0.2, 0.3, 0.5],
    "materials": {
      "mirror": {"kd": [0, 0, 0], "ks": [0, 0, 0], "mirror": [0.9, 0.9, 0.9]},
      "glass": {"kd": [0, 0, 0], "ks": [0, 0, 0], "transmission": [1, 1, 1], "ior": 1.5},
      "lamp": {"kd": [0, 0, 0], "emission": [10, 10, 10]}
    },
    "objects": [
      {"type": "sphere", "material": "mirror", "center": [-1.1, 0, 0], "radius": 1},
      {"type": "sphere", "material": "glass", "center": [1.1, 0, 0], "radius": 1},
      {"type": "quad", "material": "lamp", "vertices": [[-1, 3, -1], [1, 3, -1], [1, 3, 1], [-1, 3, 1]]}
    ]
  })",
                                     "specular_only.json", ".");
  const SplitRender r = renderPath(scene, {}, 32, 24, 16, 3, true);
  for (LightPathClass c : {LightPathClass::DirectLighting, LightPathClass::GlossyReflection,
                           LightPathClass::DiffuseInterreflection, LightPathClass::Caustics,
                           LightPathClass::SkyLight})
    EXPECT_TRUE(allZero(r.classes[static_cast<size_t>(c)])) << lightPathClassName(c);
  for (LightPathClass c : {LightPathClass::Emission, LightPathClass::MirrorReflection, LightPathClass::Refraction})
    EXPECT_FALSE(allZero(r.classes[static_cast<size_t>(c)])) << lightPathClassName(c);
}

// effects=measured leaves classes out without touching the others' random streams: the picture is the full
// picture minus exactly the left-out classes, same seed.
TEST(LightPathClasses, LeavingClassesOutRemovesExactlyThoseClasses) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/whitted_1980.json");
  const SplitRender full = renderPath(scene, {}, 40, 30, 8, 5, true);
  const SplitRender measured =
      renderPath(scene, {{"effects", "measured"}, {"effects_tolerance", "0.01"}}, 40, 30, 8, 5, false);
  ASSERT_TRUE(measured.stats.skipped.has_value());
  const LightPathMask left = measured.stats.skipped->leftOut;
  EXPECT_TRUE(left & lightPathBit(LightPathClass::DiffuseInterreflection)) << measured.stats.skipped->skipped;
  EXPECT_FALSE(left & lightPathBit(LightPathClass::DirectLighting)) << measured.stats.skipped->skipped;
  EXPECT_LE(measured.stats.skipped->errorAddedHigh, 0.01);
  double worst = 0.0;
  for (size_t i = 0; i < full.picture.pixels().size(); ++i)
    for (int ch = 0; ch < 3; ++ch) {
      double expected = 0.0;
      for (int c = 0; c < kLightPathClassCount; ++c)
        if (!(left & lightPathBit(lightPathClassAt(c))))
          expected += static_cast<double>(full.classes[static_cast<size_t>(c)].pixels()[i][ch]);
      const double got = measured.picture.pixels()[i][ch];
      worst = std::max(worst, std::abs(got - expected) / (std::abs(expected) + 1e-3));
    }
  EXPECT_LT(worst, 1e-5);
}

// effects=measured on the Cornell box and the Whitted scene: what it leaves out changes a converged picture by no
// more than the tolerance. The truth at the probe's size from two independent 256-spp renders: the product of
// their left-out parts estimates its square without their noise.
TEST(LightPathClasses, EffectsMeasuredStayWithinTheTolerance) {
  for (const char* name : {"cornell_box", "whitted_1980"}) {
    const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/" + name + ".json");
    const SplitRender measured = renderPath(scene, {{"effects", "measured"}}, 16, 12, 1, 1, false);
    ASSERT_TRUE(measured.stats.skipped.has_value()) << name;
    const SkippedWork& w = *measured.stats.skipped;
    EXPECT_LE(w.errorAddedHigh, w.tolerance) << name;
    const int width = LightPathProbeSettings{}.width, height = width * scene.camera.height / scene.camera.width;
    const SplitRender a = renderPath(scene, {}, width, height, 256, 7, true);
    const SplitRender b = renderPath(scene, {}, width, height, 256, 8, true);
    const auto leftOut = [&](const SplitRender& r, size_t i, int ch) {
      double sum = 0.0;
      for (int c = 0; c < kLightPathClassCount; ++c)
        if (w.leftOut & lightPathBit(lightPathClassAt(c)))
          sum += static_cast<double>(r.classes[static_cast<size_t>(c)].pixels()[i][ch]);
      return sum;
    };
    double truth = 0.0;
    for (size_t i = 0; i < a.picture.pixels().size(); ++i)
      for (int ch = 0; ch < 3; ++ch) {
        const double p = 0.5 * (static_cast<double>(a.picture.pixels()[i][ch]) + static_cast<double>(b.picture.pixels()[i][ch]));
        truth += leftOut(a, i, ch) * leftOut(b, i, ch) / (p * p + 1e-2);
      }
    truth /= static_cast<double>(3 * a.picture.pixels().size());
    // The probe decides by its 95 % bound; the truth here is itself an estimate (about 5 % uncertain for a
    // caustic): 10 % of room for it.
    EXPECT_LE(truth, 1.1 * w.tolerance) << name << ": left out " << w.skipped << ", probe said " << w.errorAdded;
    std::printf("[ effects ] %s: left out %s, relMSE %.3g (probe %.3g, bound %.3g), %.0f %% less time per sample\n",
                name, w.skipped.c_str(), truth, w.errorAdded, w.errorAddedHigh,
                w.secondsPerPassFull > 0 ? 100.0 * (1.0 - w.secondsPerPassSkipping / w.secondsPerPassFull) : 0.0);
  }
}

// Radiosity splits its picture by bounce: E is path's emission, K E its direct lighting, K^2 E + ... its
// diffuse interreflection. The parts add up to the picture, each is the picture of show=bounce (bounce 0, 1)
// or what those leave, and the shares agree with path's on the Cornell box (radiosity's patches and path's
// noise: within 2.5 percentage points; measured 55.0/22.0/23.0 % against 53.1/23.0/23.9 % at 160 px).
TEST(LightPathClasses, RadiositySplitsByBounceAsPathDoes) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/cornell_box.json");
  const Sets rad = {{"hemicube_res", "24"}};
  const SplitRender split = renderSplit("radiosity", scene, rad, 48, 48, 2, 1, true);
  ASSERT_EQ(split.classes.size(), static_cast<size_t>(kLightPathClassCount));
  const auto cls = [&](LightPathClass c) -> const Image& { return split.classes[static_cast<size_t>(c)]; };
  const auto bounceImage = [&](int k) {
    Sets sets = rad;
    sets.push_back({"show", "bounce"});
    sets.push_back({"bounce", std::to_string(k)});
    return renderSplit("radiosity", scene, sets, 48, 48, 2, 1, false).picture;
  };
  const Image e = bounceImage(0), ke = bounceImage(1);
  for (size_t i = 0; i < split.picture.pixels().size(); ++i)
    for (int ch = 0; ch < 3; ++ch) {
      const float p = split.picture.pixels()[i][ch];
      float sum = 0.0f;
      for (const Image& c : split.classes) sum += c.pixels()[i][ch];
      ASSERT_NEAR(sum, p, 1e-5f * (1.0f + p)) << "pixel " << i;
      ASSERT_NEAR(cls(LightPathClass::Emission).pixels()[i][ch], e.pixels()[i][ch], 1e-6f * (1.0f + p));
      ASSERT_NEAR(cls(LightPathClass::DirectLighting).pixels()[i][ch], ke.pixels()[i][ch], 1e-5f * (1.0f + p));
      for (LightPathClass none : {LightPathClass::MirrorReflection, LightPathClass::Refraction,
                                  LightPathClass::GlossyReflection, LightPathClass::Caustics, LightPathClass::SkyLight})
        ASSERT_EQ(cls(none).pixels()[i][ch], 0.0f);
    }
  const SplitRender path = renderPath(scene, {}, 48, 48, 64, 1, true);
  ASSERT_EQ(split.stats.lightPaths.size(), path.stats.lightPaths.size());
  for (size_t c = 0; c < path.stats.lightPaths.size(); ++c)
    EXPECT_NEAR(split.stats.lightPaths[c].luminanceShare, path.stats.lightPaths[c].luminanceShare, 0.025)
        << lightPathClassName(lightPathClassAt(static_cast<int>(c)));
  // Where radiosity has no F to take powers of (progressive refinement), it does not split.
  const SplitRender progressive = renderSplit("radiosity", scene, {{"progressive", "true"}}, 16, 16, 1, 1, true);
  EXPECT_TRUE(progressive.classes.empty());
  EXPECT_TRUE(progressive.stats.lightPaths.empty());
}

// Whitted with effects=measured measures its own picture with and without refraction and mirror-reflection
// rays. On its scene both show: nothing is left out and the picture is the full one. Allowed everything, it
// leaves both out and its picture is ray casting's with shadows (max_depth=0), exactly. With the glass
// shrunk to a bead (2 cm of 60) the refraction rays' light no longer shows: they are left out, and the
// full-size picture differs from the full render by less than the tolerance.
TEST(LightPathClasses, WhittedLeavesOutRaysWhoseLightDoesNotShow) {
  const std::string path = std::string(LIGHTLAB_DATA_DIR) + "/scenes/whitted_1980.json";
  const Scene scene = loadScene(path);
  const SplitRender full = renderSplit("whitted", scene, {}, 64, 48, 2, 3, false);
  const SplitRender measured = renderSplit("whitted", scene, {{"effects", "measured"}}, 64, 48, 2, 3, false);
  ASSERT_TRUE(measured.stats.skipped.has_value());
  EXPECT_EQ(measured.stats.skipped->leftOut, 0u) << measured.stats.skipped->skipped;
  EXPECT_EQ(compareImages(measured.picture, full.picture).maxAbs, 0.0);
  const SplitRender all = renderSplit("whitted", scene, {{"effects", "measured"}, {"effects_tolerance", "1"}}, 64,
                                      48, 2, 3, false);
  ASSERT_TRUE(all.stats.skipped.has_value());
  EXPECT_EQ(all.stats.skipped->leftOut,
            lightPathBit(LightPathClass::Refraction) | lightPathBit(LightPathClass::MirrorReflection));
  EXPECT_GT(all.stats.skipped->errorAdded, 1e-3);
  EXPECT_EQ(all.stats.work.rays[static_cast<size_t>(RayKind::Refraction)], 0u);
  EXPECT_EQ(all.stats.work.rays[static_cast<size_t>(RayKind::Reflection)], 0u);
  const SplitRender depth0 = renderSplit("whitted", scene, {{"max_depth", "0"}}, 64, 48, 2, 3, false);
  EXPECT_EQ(compareImages(all.picture, depth0.picture).maxAbs, 0.0);

  nlohmann::json j = nlohmann::json::parse(std::ifstream(path));
  for (auto& o : j["objects"])
    if (o.contains("radius") && o["material"] != "mirror") o["radius"] = o["radius"].get<double>() / 30.0;
  const std::string bead = ::testing::TempDir() + "whitted_bead.json";
  std::ofstream(bead) << j.dump();
  const Scene small = loadScene(bead);
  const SplitRender beadFull = renderSplit("whitted", small, {}, 160, 120, 1, 3, false);
  const SplitRender beadMeasured = renderSplit("whitted", small, {{"effects", "measured"}}, 160, 120, 1, 3, false);
  ASSERT_TRUE(beadMeasured.stats.skipped.has_value());
  const SkippedWork& w = *beadMeasured.stats.skipped;
  EXPECT_EQ(w.leftOut, lightPathBit(LightPathClass::Refraction)) << w.skipped;
  EXPECT_LE(w.errorAdded, kDefaultEffectsTolerance);
  EXPECT_GT(beadFull.stats.work.rays[static_cast<size_t>(RayKind::Refraction)], 0u);
  EXPECT_EQ(beadMeasured.stats.work.rays[static_cast<size_t>(RayKind::Refraction)], 0u);
  const double real = compareImages(beadMeasured.picture, beadFull.picture).relmse;
  EXPECT_GT(real, 0.0);
  EXPECT_LE(real, kDefaultEffectsTolerance);
  std::printf("[ effects ] whitted, glass bead: left out %s, relMSE %.2g at 160x120 (measured %.2g on the probe)\n",
              w.skipped.c_str(), real, w.errorAdded);
}

// Radiosity with effects=measured shoots only while the light still unshot shows: on the Cornell box it
// leaves some patches' rows uncomputed, estimates the error it adds within the tolerance, and its picture
// differs from the converged progressive solve's by less than the tolerance (measured 3e-4 at 4725 patches).
TEST(LightPathClasses, RadiosityStopsShootingWhenTheUnshotLightDoesNotShow) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/cornell_box.json");
  const Sets coarse = {{"hemicube_res", "16"}, {"patch_size", "0.03"}};
  Sets measuredSets = coarse, fullSets = coarse;
  measuredSets.push_back({"effects", "measured"});
  fullSets.push_back({"progressive", "true"});
  const SplitRender measured = renderSplit("radiosity", scene, measuredSets, 64, 64, 1, 1, false);
  const SplitRender full = renderSplit("radiosity", scene, fullSets, 64, 64, 1, 1, false);
  ASSERT_TRUE(measured.stats.skipped.has_value());
  const SkippedWork& w = *measured.stats.skipped;
  EXPECT_GT(w.errorAdded, 0.0) << w.skipped;
  EXPECT_LE(w.errorAdded, kDefaultEffectsTolerance);
  EXPECT_NE(w.saved.find("hemicube rows computed"), std::string::npos) << w.saved;
  const double real = compareImages(measured.picture, full.picture).relmse;
  EXPECT_LE(real, kDefaultEffectsTolerance);
  std::printf("[ effects ] radiosity, Cornell box: %s; %s; relMSE %.2g (estimated %.2g)\n", w.skipped.c_str(),
              w.saved.c_str(), real, w.errorAdded);
}

// The probe's relMSE of the picture without a class, from 16 batches of 4 spp, against the same quantity from
// a 1024-spp render (whose own noise is small against the class): within the probe's 95 % interval widened by
// 20 % for the reference's own error.
TEST(LightPathProbe, RelMseWithoutAClassAgreesWithAConvergedRender) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/cornell_box.json");
  const AcceleratorInfo& a = findAccelerator("bvh");
  const auto accel = buildAccelerator(a, ParamSet(a.name, a.params), scene.geometry);
  const TechniqueInfo& t = findTechnique("path");
  LightPathProbeSettings ps;
  ps.width = 24;
  ps.batches = 16;
  ps.budgetSeconds = 1e9;
  const LightPathProbe probe(scene, *accel, t, ParamSet(t.name, t.params), ps);
  EXPECT_EQ(probe.batches(), 16);
  const SplitRender ref = renderPath(scene, {}, probe.width(), probe.height(), 1024, 99, true);
  const LightPathClass c = LightPathClass::DiffuseInterreflection;
  double truth = 0.0;
  const Image& cls = ref.classes[static_cast<size_t>(c)];
  for (size_t i = 0; i < cls.pixels().size(); ++i)
    for (int ch = 0; ch < 3; ++ch) {
      const double v = cls.pixels()[i][ch], p = ref.picture.pixels()[i][ch];
      truth += v * v / (p * p + 1e-2);
    }
  truth /= static_cast<double>(3 * cls.pixels().size());
  const Estimate e = probe.relMseWithout(lightPathBit(c));
  EXPECT_GT(truth, 0.01);  // the Cornell box's indirect light shows
  EXPECT_GE(truth, e.low * 0.8) << e.value << " [" << e.low << ", " << e.high << "]";
  EXPECT_LE(truth, e.high * 1.2) << e.value << " [" << e.low << ", " << e.high << "]";
  // Nothing left out: no error; classes that do not occur: none either, and no share.
  EXPECT_EQ(probe.relMseWithout(0).value, 0.0);
  EXPECT_EQ(probe.relMseWithout(lightPathBit(LightPathClass::Caustics)).high, 0.0);
  EXPECT_EQ(probe.share(LightPathClass::Refraction).high, 0.0);
  double shares = 0.0;
  for (int k = 0; k < kLightPathClassCount; ++k) shares += probe.share(lightPathClassAt(k)).value;
  EXPECT_NEAR(shares, 1.0, 1e-9);
}

}  // namespace
}  // namespace ll
