// Cross-module tests of the render pipeline: cli::setUpScene (registry,
// parameter routing, scene loading, accelerator build), RenderJob (passes,
// cancellation, statistics), FrameBuffer (accumulation, stub marking) and a
// real render of the Cornell box.
#include <algorithm>
#include <atomic>
#include <functional>
#include <limits>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "test_support.h"
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include "cli/scene_setup.h"
#include "core/error.h"
#include "metrics/image_metrics.h"
#include "modules/registry.h"
#include "render/frame_buffer.h"
#include "render/render_job.h"
#include "render/student_task.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

const std::string kScenes = std::string(LIGHTLAB_DATA_DIR) + "/scenes/";

using testing_support::contains;
using testing_support::errorOf;

// A PixelTechnique for testing the machinery: every sample is a function of
// (x, y, pass) given at construction, with optional hooks.
class ScriptedTechnique final : public PixelTechnique {
 public:
  std::function<Rgb(const PixelSample&)> sample = [](const PixelSample&) { return Rgb(1.0f); };

 protected:
  Rgb renderSample(const RenderContext&, const PixelSample& s, const Tracer&) const override { return sample(s); }
};

// --- FrameBuffer ---------------------------------------------------------------------

TEST(FrameBuffer, AccumulatesTheMeanOfCompletedPasses) {
  FrameBuffer fb(3, 2);
  EXPECT_EQ(fb.width(), 3);
  EXPECT_EQ(fb.height(), 2);
  EXPECT_EQ(fb.passes(), 0);
  EXPECT_EQ(fb.resolve().pixels(), std::vector<Rgb>(6, Rgb(0.0f)));  // no pass yet: black, not NaN
  for (int pass = 0; pass < 4; ++pass) {
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 3; ++x) fb.add(x, y, Rgb(static_cast<float>(pass), static_cast<float>(x), static_cast<float>(y)));
    fb.completePass();
  }
  EXPECT_EQ(fb.passes(), 4);
  const Image img = fb.resolve();
  EXPECT_EQ(img.at(2, 1), Rgb(1.5f, 2.0f, 1.0f));  // mean of 0..3 = 1.5
  EXPECT_EQ(img.at(0, 0), Rgb(1.5f, 0.0f, 0.0f));
  EXPECT_FALSE(fb.anyStub());
  fb.clear();
  EXPECT_EQ(fb.passes(), 0);
  EXPECT_EQ(fb.resolve().at(2, 1), Rgb(0.0f));
}

TEST(FrameBuffer, StubPixelsGetMagentaStripes) {
  FrameBuffer fb(16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) fb.add(x, y, Rgb(0.25f));
  fb.markStub(3, 4);  // (3 + 4) % 8 = 7: not on a stripe
  fb.markStub(5, 3);  // (5 + 3) % 8 = 0: on a stripe
  fb.markStub(0, 1);  // 1: on a stripe
  fb.completePass();
  EXPECT_TRUE(fb.anyStub());
  const Image marked = fb.resolve(true);
  EXPECT_EQ(marked.at(5, 3), Rgb(1.0f, 0.0f, 1.0f));
  EXPECT_EQ(marked.at(0, 1), Rgb(1.0f, 0.0f, 1.0f));
  EXPECT_EQ(marked.at(3, 4), Rgb(0.25f));
  EXPECT_EQ(marked.at(8, 0), Rgb(0.25f)) << "unmarked pixels on a stripe diagonal stay as rendered";
  EXPECT_EQ(fb.resolve(false).pixels(), std::vector<Rgb>(256, Rgb(0.25f)));
  fb.clear();
  EXPECT_FALSE(fb.anyStub());
}

// --- RenderJob with a scripted technique ---------------------------------------------

struct Fixture {
  Scene scene;
  ParamSet params;
  std::unique_ptr<Accelerator> accel;
  Fixture() {
    scene = loadScene(kScenes + "tests/sphere_point_light.json");
    const AcceleratorInfo& info = findAccelerator("none");
    accel = buildAccelerator(info, ParamSet("accelerator 'none'", info.params), scene.geometry);
  }
};

RenderSettings settings(int w, int h, int spp) {
  RenderSettings s;
  s.width = w;
  s.height = h;
  s.spp = spp;
  return s;
}

TEST(RenderJob, ProgressivePassesAreCountedAndAveraged) {
  Fixture f;
  ScriptedTechnique technique;
  technique.sample = [](const PixelSample& s) { return Rgb(static_cast<float>(s.pass), 1.0f, 0.0f); };
  RenderJob job(f.scene, *f.accel, technique, f.params, settings(20, 12, 5));
  std::vector<std::pair<int, int>> calls;
  job.run([&](int done, int total) { calls.emplace_back(done, total); });
  const std::vector<std::pair<int, int>> expected = {{1, 5}, {2, 5}, {3, 5}, {4, 5}, {5, 5}};
  EXPECT_EQ(calls, expected);
  EXPECT_EQ(job.stats().passes, 5);
  EXPECT_EQ(job.frame().passes(), 5);
  EXPECT_FALSE(job.stats().cancelled);
  EXPECT_EQ(job.stats().width, 20);
  EXPECT_EQ(job.stats().spp, 5);
  EXPECT_GE(job.stats().renderSeconds, 0.0);
  EXPECT_TRUE(job.stats().missingTasks.empty());
  // Mean of passes 0..4 = 2 in every pixel.
  EXPECT_EQ(job.frame().resolve().pixels(), std::vector<Rgb>(240, Rgb(2.0f, 1.0f, 0.0f)));
}

TEST(RenderJob, SamplePositionsAreStratifiedInsideThePixel) {
  Fixture f;
  ScriptedTechnique technique;
  std::atomic<int> outside{0}, centre{0};
  technique.sample = [&](const PixelSample& s) {
    const Vec2 o = s.position - Vec2(static_cast<float>(s.x), static_cast<float>(s.y));
    if (o.x < 0.0f || o.x >= 1.0f || o.y < 0.0f || o.y >= 1.0f) ++outside;
    if (o == Vec2(0.5f)) ++centre;
    return Rgb(o, 0.0f);
  };
  RenderJob job(f.scene, *f.accel, technique, f.params, settings(8, 8, 4));
  job.run();
  EXPECT_EQ(outside.load(), 0);
  EXPECT_EQ(centre.load(), 0) << "with 4 spp no sample sits at the exact centre";
  // 4 strata of a 2x2 grid: the mean offset is close to the centre.
  const Rgb m = job.frame().resolve().mean();
  EXPECT_NEAR(m.r, 0.5f, 0.05f);
  EXPECT_NEAR(m.g, 0.5f, 0.05f);

  RenderJob single(f.scene, *f.accel, technique, f.params, settings(8, 8, 1));
  single.run();
  EXPECT_EQ(centre.load(), 64) << "one sample per pixel: the pixel centre";
}

TEST(RenderJob, NonFiniteSamplesAreCountedAndZeroed) {
  Fixture f;
  ScriptedTechnique technique;
  technique.sample = [](const PixelSample& s) {
    if (s.x == 1 && s.y == 2) return Rgb(std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f);
    if (s.x == 3 && s.y == 0) return Rgb(0.0f, kInfinity, 0.0f);
    return Rgb(0.5f);
  };
  RenderJob job(f.scene, *f.accel, technique, f.params, settings(4, 4, 3));
  job.run();
  EXPECT_EQ(job.stats().work.nonFinite, 6u);  // 2 pixels x 3 passes
  const Image img = job.frame().resolve();
  EXPECT_EQ(img.at(1, 2), Rgb(0.0f));
  EXPECT_EQ(img.at(3, 0), Rgb(0.0f));
  EXPECT_EQ(img.at(0, 0), Rgb(0.5f));
}

TEST(RenderJob, StubMarksThePixelsThatUsedIt) {
  Fixture f;
  ScriptedTechnique technique;
  technique.sample = [](const PixelSample& s) {
    if (s.x < 8) LIGHTLAB_TODO("T.1", "a test stub");
    return Rgb(0.5f);
  };
  const tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
  RenderJob job(f.scene, *f.accel, technique, f.params, settings(32, 32, 2));
  job.run();
  ASSERT_EQ(job.stats().missingTasks.size(), 1u);
  EXPECT_EQ(job.stats().missingTasks.at("T.1"), "a test stub");
  EXPECT_TRUE(job.frame().anyStub());
  const Image marked = job.frame().resolve(true);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const bool stripe = x < 8 && (x + y) % 8 < 2;
      ASSERT_EQ(marked.at(x, y), stripe ? Rgb(1.0f, 0.0f, 1.0f) : Rgb(0.5f)) << x << "," << y;
    }
  EXPECT_EQ(job.frame().resolve(false).pixels(), std::vector<Rgb>(32 * 32, Rgb(0.5f)));
  // The thread-local stub flag does not leak out of the render.
  EXPECT_FALSE(takeStubFlag());
}

// The GUI runs a preview job and then the full job in the same stack slot:
// the second log lives at the first one's address and must still hear every
// stub (a per-thread cache keyed by address once hid them).
TEST(TaskLog, ALogAtAFreedLogsAddressStillHearsEveryStub) {
  std::optional<TaskLog> log;
  const void* firstAddress = nullptr;
  for (int round = 0; round < 3; ++round) {
    log.emplace();
    if (round == 0) firstAddress = &*log;
    ASSERT_EQ(static_cast<const void*>(&*log), firstAddress);
    {
      const ScopedTaskLog scope(&*log);
      LIGHTLAB_TODO("T.2", "a stub called twice");
      LIGHTLAB_TODO("T.2", "a stub called twice");
    }
    EXPECT_EQ(log->missing().size(), 1u) << "round " << round;
    log->clear();
    {
      const ScopedTaskLog scope(&*log);
      LIGHTLAB_TODO("T.2", "a stub called twice");
    }
    EXPECT_EQ(log->missing().size(), 1u) << "after clear, round " << round;
  }
  takeStubFlag();
}

TEST(RenderJob, CancelFromAnotherThreadAfterTheFirstPass) {
  const Scene scene = loadScene(kScenes + "cornell_box.json");
  const TechniqueInfo& info = findTechnique("raycast");
  ParamSet params("technique 'raycast'", info.params);
  params.set("intersection", "framework");
  const AcceleratorInfo& accelInfo = findAccelerator("none");
  const auto accel = buildAccelerator(accelInfo, ParamSet("accelerator 'none'", accelInfo.params), scene.geometry);
  const auto technique = info.make();
  RenderJob job(scene, *accel, *technique, params, settings(32, 32, 64));

  std::atomic<bool> firstPassDone{false};
  std::thread canceller([&] {
    while (!firstPassDone.load()) std::this_thread::yield();
    job.cancel();
  });
  std::vector<int> done;
  job.run([&](int d, int total) {
    EXPECT_EQ(total, 64);
    done.push_back(d);
    if (d == 1) {
      firstPassDone = true;
      // Wait (bounded) for the other thread's cancel, so the outcome is exact.
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
      while (!job.cancelled() && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
    }
  });
  canceller.join();
  EXPECT_TRUE(job.cancelled());
  EXPECT_TRUE(job.stats().cancelled);
  EXPECT_EQ(job.stats().passes, 1);
  EXPECT_LT(job.stats().passes, 64);
  EXPECT_EQ(job.frame().passes(), 1);
  EXPECT_EQ(done, std::vector<int>{1});
  EXPECT_EQ(job.stats().work.rays[static_cast<size_t>(RayKind::Camera)], 32u * 32u)
      << "exactly one pass of camera rays";
  const Image image = job.frame().resolve();
  for (const Rgb& p : image.pixels()) ASSERT_TRUE(isFinite(p));
}

TEST(RenderJob, CancelMidPassStopsAfterTheTileInProgress) {
  Fixture f;
  ScriptedTechnique technique;
  RenderJob* self = nullptr;
  std::atomic<int> samples{0};
  technique.sample = [&](const PixelSample& s) {
    ++samples;
    if (s.pass == 2 && s.x == 0 && s.y == 0) self->cancel();  // first tile of the third pass
    return Rgb(1.0f);
  };
  const tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
  RenderJob job(f.scene, *f.accel, technique, f.params, settings(64, 64, 10));
  self = &job;
  job.run();
  EXPECT_TRUE(job.stats().cancelled);
  EXPECT_EQ(job.stats().passes, 2);
  EXPECT_EQ(job.frame().passes(), 2);
  // Two full passes plus at most the one 16x16 tile in which cancel() was called.
  EXPECT_GE(samples.load(), 2 * 64 * 64 + 1);
  EXPECT_LE(samples.load(), 2 * 64 * 64 + 16 * 16);
}

// Known bug (reported, not fixed here): the samples of a pass interrupted by
// cancel() stay in the frame buffer's sums, but the pass is not counted, so
// resolve() divides (passes + 1) samples by `passes` in the tiles that were
// rendered: those pixels come out too bright (here 1.5 instead of 1).
TEST(RenderJob, CancelledPassDoesNotBrightenTheImage) {
  Fixture f;
  ScriptedTechnique technique;
  RenderJob* self = nullptr;
  technique.sample = [&](const PixelSample& s) {
    if (s.pass == 2 && s.x == 0 && s.y == 0) self->cancel();
    return Rgb(1.0f);
  };
  const tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
  RenderJob job(f.scene, *f.accel, technique, f.params, settings(64, 64, 10));
  self = &job;
  job.run();
  ASSERT_EQ(job.frame().passes(), 2);
  EXPECT_EQ(job.frame().resolve().at(0, 0), Rgb(1.0f));
}

TEST(RenderJob, CancelBeforeRunRendersNothing) {
  Fixture f;
  ScriptedTechnique technique;
  RenderJob job(f.scene, *f.accel, technique, f.params, settings(8, 8, 4));
  job.cancel();
  int calls = 0;
  job.run([&](int, int) { ++calls; });
  EXPECT_EQ(calls, 0);
  EXPECT_TRUE(job.stats().cancelled);
  EXPECT_EQ(job.stats().passes, 0);
  EXPECT_EQ(job.stats().work.totalRays(), 0u);
}

// --- cli::setUpScene -------------------------------------------------------------------

TEST(SceneSetup, UnknownTechniqueListsKnownOnesBeforeLoading) {
  // The scene does not exist: names are checked first, so the technique is named.
  const std::string msg = errorOf([] { cli::setUpScene(kScenes + "nope.json", "phong", "none", {}); });
  EXPECT_TRUE(contains(msg, "unknown technique 'phong' (known: ")) << msg;
  EXPECT_TRUE(contains(msg, "raycast")) << msg;
  EXPECT_FALSE(contains(msg, "nope.json")) << msg;
}

TEST(SceneSetup, UnknownAcceleratorListsKnownOnes) {
  const std::string msg = errorOf([] { cli::setUpScene(kScenes + "nope.json", "raycast", "kd", {}); });
  EXPECT_TRUE(contains(msg, "unknown accelerator 'kd' (known: ")) << msg;
  EXPECT_TRUE(contains(msg, "none")) << msg;
}

TEST(SceneSetup, SetAssignmentsAreValidatedBeforeLoading) {
  const std::string missing = kScenes + "nope.json";
  EXPECT_TRUE(contains(errorOf([&] { cli::setUpScene(missing, "raycast", "none", {"samples=4"}); }),
                       "technique 'raycast' has no parameter 'samples' "
                       "(parameters: light_samples, intersection, shadows)"));
  EXPECT_TRUE(contains(errorOf([&] { cli::setUpScene(missing, "raycast", "none", {"light_samples=0"}); }),
                       "parameter 'light_samples' = 0 is out of range [1, 1024]"));
  EXPECT_TRUE(contains(errorOf([&] { cli::setUpScene(missing, "raycast", "none", {"intersection=gpu"}); }),
                       "unknown value 'gpu' (one of: auto, student, framework)"));
  EXPECT_EQ(errorOf([&] { cli::setUpScene(missing, "raycast", "none", {"light_samples"}); }),
            "--set expects name=value, got 'light_samples'");
  // With valid names and values the scene itself is the error.
  EXPECT_EQ(errorOf([&] { cli::setUpScene(missing, "raycast", "none", {"light_samples=2"}); }),
            missing + ": no such scene file");
}

TEST(SceneSetup, RoutesSetToTheDeclaringModule) {
  const cli::SceneSetup s = cli::setUpScene(kScenes + "tests/shadow_quad.json", "raycast", "none",
                                            {"light_samples=7", "intersection=framework"});
  ASSERT_NE(s.technique, nullptr);
  ASSERT_NE(s.accelInfo, nullptr);
  EXPECT_EQ(s.technique->name, "raycast");
  EXPECT_EQ(s.accelInfo->name, "none");
  EXPECT_EQ(s.techniqueParams.getInt("light_samples"), 7);
  EXPECT_EQ(s.techniqueParams.getChoice("intersection"), "framework");
  EXPECT_EQ(s.techniqueParams.owner(), "technique 'raycast'");
  EXPECT_EQ(s.accelParams.owner(), "accelerator 'none'");
  EXPECT_TRUE(s.accelParams.decls().empty());
  ASSERT_NE(s.accel, nullptr);
  EXPECT_EQ(s.scene.geometry.primitiveCount(), 3u);
  EXPECT_GE(s.loadSeconds, 0.0);
  EXPECT_GE(s.buildSeconds, 0.0);
  // The accelerator is built over the loaded scene.
  Hit hit;
  QueryCounters counters;
  Ray down;
  down.origin = Vec3(0.0f, 5.0f, 0.0f);
  down.dir = Vec3(0.0f, -1.0f, 0.0f);
  ASSERT_TRUE(s.accel->intersect(down, hit, counters));
  EXPECT_NEAR(hit.t, 5.0f - 1.1f, 1e-5f);  // top of the ball
  // Defaults where nothing was set.
  const cli::SceneSetup d = cli::setUpScene(kScenes + "tests/shadow_quad.json", "raycast", "none", {});
  EXPECT_EQ(d.techniqueParams.getInt("light_samples"), 16);
  EXPECT_EQ(d.techniqueParams.getChoice("intersection"), "auto");
}

TEST(Registry, KnowsTheBuiltInModules) {
  EXPECT_EQ(findTechnique("raycast").name, "raycast");
  EXPECT_EQ(findAccelerator("none").name, "none");
  const auto names = techniqueNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "raycast"), names.end());
  const TechniqueInfo* cheapest = cheapestTechniqueFor(EffectSet{Effect::DirectLighting, Effect::HardShadows});
  ASSERT_NE(cheapest, nullptr);
  EXPECT_TRUE(cheapest->simulates.has(Effect::HardShadows));
  // Whatever is registered, the answer simulates what was asked and is the cheapest that does.
  for (const EffectSet needed : {EffectSet{}, EffectSet{Effect::Refraction}, EffectSet{Effect::SoftShadows}}) {
    const TechniqueInfo* best = cheapestTechniqueFor(needed);
    for (const TechniqueInfo& t : techniques()) {
      if (t.gpu || !t.simulates.contains(needed)) continue;  // GPU techniques need a display: never suggested
      ASSERT_NE(best, nullptr);
      EXPECT_LE(best->cost, t.cost);
    }
    if (best) {
      EXPECT_TRUE(best->simulates.contains(needed));
    }
  }
}

// --- A real render -------------------------------------------------------------------

TEST(RenderPipeline, CornellBoxRendersSanely) {
  cli::SceneSetup s = cli::setUpScene(kScenes + "cornell_box.json", "raycast", "none", {"intersection=framework"});
  const auto technique = s.technique->make();
  RenderJob job(s.scene, *s.accel, *technique, s.techniqueParams, settings(64, 64, 1));
  job.run();
  const RenderStats& stats = job.stats();
  std::string missing;
  for (const auto& [id, what] : stats.missingTasks) missing += id + " not implemented (" + what + "); ";
  ASSERT_TRUE(stats.missingTasks.empty()) << "raycast needs assignment 2: " << missing;
  EXPECT_EQ(stats.work.nonFinite, 0u);
  EXPECT_EQ(stats.work.rays[static_cast<size_t>(RayKind::Camera)], 64u * 64u);
  // Area light only: shadow rays, light_samples (16) per shaded pixel at most.
  const uint64_t shadow = stats.work.rays[static_cast<size_t>(RayKind::Shadow)];
  EXPECT_GT(shadow, 64u * 64u * 8u);
  EXPECT_LE(shadow, 64u * 64u * 16u);
  EXPECT_EQ(stats.work.rays[static_cast<size_t>(RayKind::Reflection)], 0u);
  const Image img = job.frame().resolve();
  for (const Rgb& p : img.pixels()) {
    ASSERT_TRUE(isFinite(p));
    ASSERT_GE(minComponent(p), 0.0f);
  }
  // The box fills the frame: a mean radiance of a fraction of the light's.
  const Rgb mean = img.mean();
  EXPECT_GT(mean.r, 0.1f);
  EXPECT_LT(mean.r, 3.0f);
  EXPECT_GT(mean.g, 0.05f);
  EXPECT_GT(mean.r, mean.b) << "warm light, red wall";
  // The pixel looking at the light shows its emission (plus a little ambient).
  const Rgb light = img.at(32, 9);
  EXPECT_NEAR(light.r, 18.387f + 0.78f * 0.05f, 0.05f);
  EXPECT_NEAR(light.b, 6.75357f + 0.78f * 0.05f, 0.05f);
  // Red wall on the left, green on the right (image right is -x).
  const Rgb left = img.at(3, 32), right = img.at(60, 32);
  EXPECT_GT(left.r, 2.0f * left.g);
  EXPECT_GT(right.g, 2.0f * right.r);
  // Statistics serialise with the same counts.
  const nlohmann::json j = stats.toJson();
  EXPECT_EQ(j["rays"]["camera"].get<uint64_t>(), 64u * 64u);
  EXPECT_EQ(j["non_finite_samples"].get<uint64_t>(), 0u);
  EXPECT_FALSE(j["cancelled"].get<bool>());
}

// One shadow ray per area light and pass is an unbiased estimate: over passes it converges to the
// soft shadow of many light samples. (It sampled the light's centre, a point light: a hard shadow in
// every pass, which no number of passes softened -- the soft-shadow demo's 1-sample side.)
TEST(RenderPipeline, OneLightSampleAPassConvergesToTheSoftShadow) {
  const auto render = [](int lightSamples, int spp) {
    cli::SceneSetup s = cli::setUpScene(kScenes + "cornell_box.json", "raycast", "bvh",
                                        {"intersection=framework", "light_samples=" + std::to_string(lightSamples)});
    const auto technique = s.technique->make();
    RenderJob job(s.scene, *s.accel, *technique, s.techniqueParams, settings(48, 48, spp));
    job.run();
    return job.frame().resolve();
  };
  // Against 16 light samples a pass, at the same passes (the same pixel positions: only the light
  // sampling differs). Without bias the error falls like 1/passes; a fixed light point keeps its
  // hard shadow.
  const double error = compareImages(render(1, 64), render(16, 64)).relmse;
  const double noisy = compareImages(render(1, 4), render(16, 4)).relmse;
  std::printf("relMSE of 1 light sample a pass against 16: %.5f after 4 passes, %.5f after 64\n", noisy, error);
  EXPECT_LT(error, 0.002) << "1 light sample a pass, 64 passes";
  EXPECT_GT(noisy, 4.0 * error) << "more passes remove the noise (4 passes: " << noisy << ")";
}

}  // namespace
}  // namespace ll
