// The GUI's actions without a window: a broken scene or preset leaves the
// previous state usable with a message, a file change reloads, switching
// technique or accelerator keeps each one's own parameters, and panes restart on any change.
#include "gui/app_actions.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "modules/registry.h"
#include "render/render_job.h"
#include "test_support.h"

namespace ll::gui {
namespace {

namespace fs = std::filesystem;
using testing_support::contains;

const std::string kScenes = std::string(LIGHTLAB_DATA_DIR) + "/scenes/";

void waitPanes(AppState& app) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (std::chrono::steady_clock::now() < deadline) {
    submitPanes(app);
    refreshPanes(app);
    if (allPanesFinished(app)) {
      app.background->drain();
      refreshPanes(app);  // collects the errors computed in the background
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  FAIL() << "panes did not finish";
}

// Tiny renders (32 x 24, one pass) so the tests stay fast.
void makeSmall(AppState& app) {
  initPanes(app);
  for (int i = 0; i < kMaxPanes; ++i)
    setTechnique(app, i, "raycast");  // headless: no GPU techniques
  app.width = 32;
  app.height = 24;
  for (PaneState& p : app.panes) p.spp = 1;
}

// A copy of a small scene in its own temporary folder (the watcher tests change and delete it).
fs::path copyOfScene(const std::string& folder) {
  const fs::path dir = fs::temp_directory_path() / folder;
  fs::create_directories(dir);
  const fs::path file = dir / "scene.json";
  fs::copy_file(kScenes + "tests/sphere_point_light.json", file, fs::copy_options::overwrite_existing);
  return file;
}

// Small panes (makeSmall) on the scene at `file`, loaded.
void openSmall(AppState& app, const fs::path& file) {
  makeSmall(app);
  openScene(app, file.string());
  waitForSceneLoad(app);
}

// What the GUI does every frame, once the watch's half second has passed: look at the file, finish a load.
void lookAgain(AppState& app) {
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  watchSceneFile(app);
  waitForSceneLoad(app);
}

TEST(AppActions, ABrokenSceneKeepsThePreviousOneAndSaysWhere) {
  AppState app;
  makeSmall(app);
  openScene(app, kScenes + "cornell_box.json");
  waitForSceneLoad(app);
  ASSERT_TRUE(app.scene);
  const uint64_t version = app.sceneVersion;
  const auto* before = app.scene.get();

  openScene(app, kScenes + "tests/bad/malformed_json.json");
  waitForSceneLoad(app);
  EXPECT_EQ(app.scene.get(), before);
  EXPECT_EQ(app.sceneVersion, version);
  EXPECT_EQ(app.scenePath, kScenes + "cornell_box.json");
  ASSERT_FALSE(app.messages.empty());
  EXPECT_TRUE(app.messages.back().error);
  EXPECT_TRUE(contains(app.messages.back().text, "malformed_json.json:"))
      << app.messages.back().text;

  openScene(app, "/nonexistent.json");
  waitForSceneLoad(app);
  EXPECT_EQ(app.scene.get(), before);
  EXPECT_TRUE(contains(app.messages.back().text, "/nonexistent.json")) << app.messages.back().text;

  waitPanes(app);  // and it still renders
  EXPECT_EQ(app.panes[0].shown.phase, PaneSnapshot::Phase::Done);
}

TEST(AppActions, ChangingTheSceneFileOnDiskReloadsItKeepingTheView) {
  const fs::path file = copyOfScene("lightlab_reload_test");
  AppState app;
  openSmall(app, file);
  ASSERT_TRUE(app.scene);
  const uint64_t version = app.sceneVersion;
  app.camera.eye += Vec3(0.1f, 0, 0);  // the user moved the view

  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(2));
  lookAgain(app);  // the watch looks twice a second
  EXPECT_EQ(app.sceneVersion, version + 1);
  EXPECT_NE(app.camera.eye, app.scene->camera.eye);  // a reload keeps the view

  // A broken save is reported once, not reloaded in a loop, and the scene stays.
  std::ofstream(file) << "{ \"camera\": ";
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(4));
  lookAgain(app);
  EXPECT_EQ(app.sceneVersion, version + 1);
  EXPECT_TRUE(app.messages.back().error);
  const size_t messages = app.messages.size();
  lookAgain(app);
  EXPECT_EQ(app.messages.size(), messages);
  fs::remove_all(file.parent_path());
}

// A save made while a (slow) load runs was never picked up: the file's time was taken after the load.
TEST(AppActions, ASaveMadeDuringALoadIsReloaded) {
  const fs::path file = copyOfScene("lightlab_reload_during_load_test");
  AppState app;
  makeSmall(app);
  openScene(app, file.string());
  // The user saves while the load runs (the load may read either version: what matters is the next look).
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(2));
  waitForSceneLoad(app);
  ASSERT_TRUE(app.scene);
  const uint64_t version = app.sceneVersion;
  lookAgain(app);
  EXPECT_EQ(app.sceneVersion, version + 1) << "the save made during the load was not reloaded";
  lookAgain(app);  // and then it settles: no reload without a change
  EXPECT_EQ(app.sceneVersion, version + 1);
  fs::remove_all(file.parent_path());
}

// Deleting the watched scene said nothing; now it is said once, and the file's return reloads it.
TEST(AppActions, ADeletedSceneFileIsSaidOnceAndReloadsWhenBack) {
  const fs::path file = copyOfScene("lightlab_deleted_scene_test");
  const fs::path dir = file.parent_path();
  AppState app;
  openSmall(app, file);
  ASSERT_TRUE(app.scene);
  const uint64_t version = app.sceneVersion;
  fs::rename(file, dir / "moved.json");
  const size_t before = app.messages.size();
  for (int i = 0; i < 3; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(600));
    watchSceneFile(app);
  }
  ASSERT_EQ(app.messages.size(), before + 1);
  EXPECT_TRUE(contains(app.messages.back().text, "scene.json: the scene file is gone")) << app.messages.back().text;
  EXPECT_TRUE(app.scene) << "the scene shown stays";
  fs::rename(dir / "moved.json", file);
  lookAgain(app);
  EXPECT_EQ(app.sceneVersion, version + 1);
  fs::remove_all(dir);
}

// Four panes on the 235k bunny started a radiosity solve of minutes by default.
TEST(AppActions, TheDefaultPanesStartNoRadiositySolve) {
  AppState app;
  initPanes(app);
  for (const PaneState& p : app.panes) EXPECT_EQ(p.technique.rfind("radiosity", 0), std::string::npos) << p.technique;
  EXPECT_EQ(app.panes[0].technique, "blinn-phong");
  EXPECT_EQ(app.panes[3].technique, "path");
}

// Quitting cancels a long solve and does not wait for it.
TEST(AppActions, StopAllWorkEndsALongRadiositySolveAtOnce) {
  AppState app;
  makeSmall(app);
  openScene(app, kScenes + "cornell_box.json");
  waitForSceneLoad(app);
  ASSERT_TRUE(app.scene);
  app.paneCount = 1;
  setTechnique(app, 0, "radiosity");
  app.panes[0].techniqueParams.set("hemicube_res", "128");  // a minute or more of form factors
  submitPanes(app);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (app.panes[0].renderer->snapshot().phaseName.rfind("form factors", 0) != 0 &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ASSERT_EQ(app.panes[0].renderer->snapshot().phaseName.rfind("form factors", 0), 0u);
  EXPECT_TRUE(stopAllWork(app, 2.0)) << "the solve did not stop within 2 s";
}

TEST(AppActions, EachTechniqueAndAcceleratorKeepsItsOwnParameters) {
  AppState app;
  makeSmall(app);
  setTechnique(app, 0, "whitted");
  app.panes[0].techniqueParams.set("max_depth", "2");
  app.panes[0].techniqueParams.set("light_samples", "5");
  app.panes[0].dirty = false;
  setTechnique(app, 0, "whitted");  // the same technique: values stay, the pane restarts
  EXPECT_EQ(app.panes[0].techniqueParams.getInt("max_depth"), 2);
  EXPECT_TRUE(app.panes[0].dirty);
  // Another technique gets its own defaults, not whitted's values of the same names.
  setTechnique(app, 0, "raycast");
  EXPECT_EQ(app.panes[0].techniqueParams.getInt("light_samples"),
            ParamSet("raycast", findTechnique("raycast").params).getInt("light_samples"));
  app.panes[0].techniqueParams.set("light_samples", "3");
  setTechnique(app, 0, "whitted");  // back: whitted's own values again
  EXPECT_EQ(app.panes[0].techniqueParams.getInt("max_depth"), 2);
  EXPECT_EQ(app.panes[0].techniqueParams.getInt("light_samples"), 5);
  setTechnique(app, 0, "raycast");
  EXPECT_EQ(app.panes[0].techniqueParams.getInt("light_samples"), 3);
  // Per pane: pane B's whitted starts from the defaults.
  setTechnique(app, 1, "whitted");
  EXPECT_EQ(app.panes[1].techniqueParams.getInt("max_depth"),
            ParamSet("whitted", findTechnique("whitted").params).getInt("max_depth"));
  setAccelerator(app, 0, "bvh");
  app.panes[0].accelParams.set("max_leaf", "2");
  setAccelerator(app, 0, "kdtree");
  setAccelerator(app, 0, "bvh");
  EXPECT_EQ(app.panes[0].accelParams.getInt("max_leaf"), 2);
  setTechnique(app, 0, "no-such");
  EXPECT_TRUE(contains(app.messages.back().text, "no-such"));
  EXPECT_EQ(app.panes[0].technique, "raycast");
  setAccelerator(app, 1, "none");
  EXPECT_EQ(app.panes[1].accelerator, "none");
}

TEST(AppActions, PresetAppliesAndABadPresetChangesNothing) {
  const fs::path dir = fs::temp_directory_path() / "lightlab_app_preset_test";
  fs::create_directories(dir);
  AppState app;
  makeSmall(app);
  openScene(app, kScenes + "cornell_box.json");
  waitForSceneLoad(app);
  app.paneCount = 4;
  app.compare.mode = CompareMode::Wipe;
  app.compare.wipe = 0.25f;
  app.panes[2].techniqueParams.set("light_samples", "9");
  app.camera.eye = Vec3(100, 200, -700);
  const std::string file = (dir / "v.json").string();
  ASSERT_TRUE(savePresetFile(app, file));

  AppState other;
  makeSmall(other);
  ASSERT_TRUE(loadPresetFile(other, file));
  waitForSceneLoad(other);
  EXPECT_EQ(fs::path(other.scenePath).lexically_normal(),
            fs::path(app.scenePath).lexically_normal());
  EXPECT_EQ(other.camera.eye, app.camera.eye);  // the preset's camera, not the scene's
  EXPECT_EQ(other.paneCount, 4);
  EXPECT_EQ(other.compare.mode, CompareMode::Wipe);
  EXPECT_EQ(other.compare.wipe, 0.25f);
  EXPECT_EQ(other.panes[2].techniqueParams.getInt("light_samples"), 9);

  std::ofstream(dir / "bad.json")
      << R"({"lightlab_preset": 1, "scene": "x.json", "panes": [{"technique": "zzz"}]})";
  EXPECT_FALSE(loadPresetFile(other, (dir / "bad.json").string()));
  EXPECT_TRUE(contains(other.messages.back().text, "bad.json:1:")) << other.messages.back().text;
  EXPECT_EQ(other.paneCount, 4);
  EXPECT_EQ(other.compare.mode, CompareMode::Wipe);
  fs::remove_all(dir);
}

TEST(AppActions, ACameraChangeRestartsEveryActivePaneAndErrorsFollowTheReference) {
  AppState app;
  makeSmall(app);
  openScene(app, kScenes + "cornell_box.json");
  waitForSceneLoad(app);
  app.compare.reference = 0;
  app.panes[1].techniqueParams.set("light_samples", "1");
  waitPanes(app);
  ASSERT_TRUE(app.panes[1].hasError);
  EXPECT_GT(app.panes[1].error.rmse, 0.0);  // 1 light sample against 16: noisier shadows
  const auto before = *app.panes[0].shown.image;
  app.camera.eye += Vec3(30, 0, 0);
  app.cameraChanged = true;
  waitPanes(app);
  EXPECT_NE(app.panes[0].shown.image->pixels(), before.pixels());
  EXPECT_FALSE(app.panes[2].shown.image);  // pane C is hidden with two panes: never rendered
}

TEST(AppActions, AClickedPixelOfAWhittedPaneGetsItsRayTreeAndFollowsTheCamera) {
  AppState app;
  makeSmall(app);
  setTechnique(app, 0, "whitted");
  app.panes[0].accelerator = "bvh";
  openScene(app, kScenes + "whitted_1980.json");
  waitForSceneLoad(app);
  waitPanes(app);
  inspectPixel(app, 0, Vec2(19.5f, 10.5f));  // the glass sphere at 32 x 24
  refreshRayTree(app);
  ASSERT_TRUE(app.inspector.tree.has_value()) << app.inspector.note;
  const RayTree first = *app.inspector.tree;
  EXPECT_GT(first.nodes.size(), 5u);
  EXPECT_EQ(first.nodes[0].object, "glass_shell");
  app.camera.eye += Vec3(2, 0, 0);  // a new view: the same pixel now sees something else
  app.cameraChanged = true;
  waitPanes(app);
  refreshRayTree(app);
  ASSERT_TRUE(app.inspector.tree.has_value());
  EXPECT_NE(app.inspector.tree->nodes[0].origin, first.nodes[0].origin);
  // Ray casting's tree: the camera ray and its shadow rays, whose shares add up to the pixel.
  inspectPixel(app, 1, Vec2(10.5f, 10.5f));
  refreshRayTree(app);
  ASSERT_TRUE(app.inspector.tree.has_value()) << app.inspector.note;
  Rgb shares(0.0f);
  for (const RayTreeNode& n : app.inspector.tree->nodes) shares += n.contribution;
  EXPECT_NEAR(shares.r, app.inspector.tree->pixel.r, 1e-5f * (1.0f + app.inspector.tree->pixel.r));
  // A technique without one says so instead of drawing nothing silently.
  setTechnique(app, 1, "blinn-phong");
  waitPanes(app);
  inspectPixel(app, 1, Vec2(10.5f, 10.5f));
  refreshRayTree(app);
  EXPECT_FALSE(app.inspector.tree.has_value());
  EXPECT_TRUE(contains(app.inspector.note, "whitted")) << app.inspector.note;
}

TEST(AppActions, ADroppedFileOpensAsAPresetOrAsAScene) {
  AppState app;
  makeSmall(app);
  openDroppedFile(app, std::string(LIGHTLAB_DATA_DIR) + "/presets/light_samples_convergence.json");
  waitForSceneLoad(app);
  EXPECT_EQ(app.paneCount, 4);  // the preset's layout
  EXPECT_EQ(app.compare.reference, 3);
  ASSERT_TRUE(app.scene);
  EXPECT_TRUE(contains(app.scenePath, "cornell_box.json"));
  openDroppedFile(app, kScenes + "bunny.json");
  waitForSceneLoad(app);
  EXPECT_TRUE(contains(app.scenePath, "bunny.json"));
  EXPECT_EQ(app.paneCount, 4);  // a scene changes the scene only
  EXPECT_EQ(app.camera.eye, app.scene->camera.eye);
}

TEST(AppActions, SceneListFindsScenesButNotPresetsOrTheSchema) {
  const auto files = findSceneFiles({kScenes});
  EXPECT_TRUE(std::any_of(files.begin(), files.end(),
                          [](const std::string& f) { return contains(f, "cornell_box.json"); }));
  EXPECT_TRUE(std::none_of(files.begin(), files.end(),
                           [](const std::string& f) { return contains(f, "schema"); }));
}

}  // namespace
}  // namespace ll::gui

namespace ll::gui {
namespace {

// Whether `s`'s image is what a headless render of pane `pane`'s current view gives.
bool sameAsHeadless(const AppState& app, int pane, const PaneSnapshot& s) {
  const PaneState& p = app.panes[static_cast<size_t>(pane)];
  RenderSettings settings = renderSettings(app, p);
  settings.width = s.image->width();
  settings.height = s.image->height();
  settings.spp = s.preview ? 1 : s.passes;
  const auto accel =
      buildAccelerator(findAccelerator(p.accelerator), p.accelParams, app.scene->geometry);
  const auto technique = findTechnique(p.technique).make();
  RenderJob job(*app.scene, *accel, *technique, p.techniqueParams, settings);
  job.run();
  return job.frame().resolve().pixels() == s.image->pixels();
}

// After a camera move, every image a pane shows (its low-resolution preview,
// then the passes) is of the new view, never a stale one.
TEST(AppActions, EveryImageAfterACameraMoveShowsTheNewView) {
  AppState app;
  initPanes(app);
  for (int i = 0; i < kMaxPanes; ++i)
    setTechnique(app, i, "raycast");  // headless: no GPU techniques
  app.width = 128;
  app.height = 128;
  for (PaneState& p : app.panes) p.spp = 4;
  openScene(app, kScenes + "cornell_box.json");
  waitForSceneLoad(app);
  submitPanes(app);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  for (int i = 0; i < 3; ++i) {  // a quick drag: several moves, each cancelling the last
    app.camera.eye += Vec3(40, 10, 0);
    app.cameraChanged = true;
    submitPanes(app);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  // From now on every image the pane shows must be of the final view: sample
  // snapshots until the full render is done and check each new one.
  PaneSnapshot s;
  uint64_t checked = app.panes[1].renderer->snapshot().version;
  int images = 0;
  for (int i = 0; i < 60000 && s.phase != PaneSnapshot::Phase::Done; ++i) {
    s = app.panes[1].renderer->snapshot();
    // Previews and the finished image can be rendered headless exactly; a
    // middle pass of a stratified render cannot (strata depend on the total).
    if (s.version != checked && s.image && (s.preview || s.passes == s.totalPasses)) {
      checked = s.version;
      ++images;
      EXPECT_TRUE(sameAsHeadless(app, 1, s))
          << "image " << images << ": preview " << s.preview << ", passes " << s.passes;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_EQ(s.phase, PaneSnapshot::Phase::Done);
  EXPECT_GE(images, 1);
}

}  // namespace
}  // namespace ll::gui
