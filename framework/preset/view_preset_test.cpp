// View presets: a saved view loads back identical, and every kind of bad
// preset is one error naming file:line:col and the allowed values.
#include "preset/view_preset.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_support.h"

namespace ll {
namespace {

namespace fs = std::filesystem;
using testing_support::contains;
using testing_support::errorOf;

ViewPreset parse(const std::string& text) {
  return parsePreset(text, "p.json", "/presets");
}

TEST(ViewPreset, MinimalPresetGetsDefaultsAndFourPanes) {
  const ViewPreset p = parse(R"({"lightlab_preset": 1, "scene": "../data/cornell.json",
                                 "panes": [{"technique": "raycast"}]})");
  EXPECT_EQ(p.scene, "/data/cornell.json");  // relative to the preset's folder
  EXPECT_FALSE(p.camera.has_value());
  EXPECT_EQ(p.paneCount, 1);
  ASSERT_EQ(p.panes.size(), static_cast<size_t>(kMaxPanes));
  EXPECT_EQ(p.panes[3].technique, "raycast");
  EXPECT_EQ(p.compare.mode, CompareMode::SideBySide);
}

TEST(ViewPreset, EmbeddedPresetsMayLeaveOutTheTag) {
  const std::string text = R"({"scene": "s.json", "panes": [{"technique": "raycast"}]})";
  EXPECT_EQ(parsePreset(text, "deck.md", "/slides", true).scene, "/slides/s.json");
  EXPECT_TRUE(contains(errorOf([&] { parse(text); }), "not a LightLab view preset"));
  EXPECT_TRUE(contains(errorOf([] { parsePreset(R"({"lightlab_preset": 2, "scene": "s.json", "panes": []})", "d.md", "", true); }),
                       "needs \"lightlab_preset\": 1"));
}

TEST(ViewPreset, SaveThenLoadGivesTheSameView) {
  const fs::path dir = fs::temp_directory_path() / "lightlab_preset_test";
  fs::create_directories(dir / "scenes");
  ViewPreset p;
  p.scene = (dir / "scenes" / "s.json").string();
  Camera c;
  c.eye = Vec3(1, 2, 3);
  c.target = Vec3(0, 0.5f, -1);
  c.fovYDeg = 33.0f;
  p.camera = c;
  p.width = 320;
  p.height = 200;
  p.paneCount = 4;
  PaneSetup a;
  a.technique = "raycast";
  a.techniqueParams["light_samples"] = "3";
  a.spp = 7;
  p.panes.assign(kMaxPanes, a);
  p.panes[1].label = "K²E";
  p.panes[1].techniqueParams["intersection"] = "framework";
  p.compare.mode = CompareMode::Difference;
  p.compare.diff = DiffMode::Relative;
  p.compare.diffMax = 0.25f;
  p.compare.reference = 2;
  p.compare.paneA = 3;
  p.compare.paneB = 1;
  p.compare.wipe = 0.3f;
  p.uiScale = 1.5f;
  p.exposure = -1.0f;
  p.inspectPane = 1;
  p.inspectPixel = Vec2(12.5f, 7.5f);
  p.description = "what it shows";
  const std::string file = (dir / "view.json").string();
  savePreset(p, file);
  EXPECT_TRUE(
      contains(presetToJson(p, dir.string()).dump(), "\"scenes/s.json\""));  // stored relative

  const ViewPreset q = loadPreset(file);
  EXPECT_EQ(fs::path(q.scene).lexically_normal(), fs::path(p.scene).lexically_normal());
  ASSERT_TRUE(q.camera.has_value());
  EXPECT_EQ(q.camera->eye, c.eye);
  EXPECT_EQ(q.camera->target, c.target);
  EXPECT_EQ(q.camera->fovYDeg, c.fovYDeg);
  EXPECT_EQ(q.description, "what it shows");
  EXPECT_EQ(q.width, 320);
  EXPECT_EQ(q.height, 200);
  EXPECT_EQ(q.paneCount, 4);
  EXPECT_EQ(q.panes[0].techniqueParams.at("light_samples"), "3");
  EXPECT_EQ(q.panes[1].techniqueParams.at("intersection"), "framework");
  EXPECT_EQ(q.panes[2].spp, 7);
  EXPECT_EQ(q.panes[1].label, "K²E");
  EXPECT_EQ(q.panes[0].label, "");
  EXPECT_EQ(q.compare.mode, CompareMode::Difference);
  EXPECT_EQ(q.compare.diff, DiffMode::Relative);
  EXPECT_EQ(q.compare.diffMax, 0.25f);
  EXPECT_EQ(q.compare.reference, 2);
  EXPECT_EQ(q.compare.paneA, 3);
  EXPECT_EQ(q.compare.paneB, 1);
  EXPECT_EQ(q.compare.wipe, 0.3f);
  EXPECT_EQ(q.uiScale, 1.5f);
  EXPECT_EQ(q.exposure, -1.0f);
  EXPECT_EQ(q.inspectPane, 1);
  EXPECT_EQ(q.inspectPixel, Vec2(12.5f, 7.5f));
  fs::remove_all(dir);
}

TEST(ViewPreset, BadPresetsNameThePlaceAndTheAllowedValues) {
  const std::string head = R"({"lightlab_preset": 1, "scene": "s.json", )";
  std::string e = errorOf([&] { parse(head + "\n\"panes\": [{\"technique\": \"raytrace\"}]}"); });
  EXPECT_TRUE(contains(e, "p.json:2:")) << e;
  EXPECT_TRUE(contains(e, "raycast")) << e;  // lists the known techniques

  e = errorOf([&] {
    parse(head + R"("panes": [{"technique": "raycast", "params": {"light_samples": 0}}]})");
  });
  EXPECT_TRUE(contains(e, "p.json:1:")) << e;
  EXPECT_TRUE(contains(e, "light_samples")) << e;
  EXPECT_TRUE(contains(e, "[1, 1024]")) << e;

  e = errorOf(
      [&] { parse(head + R"("panes": [{"technique": "raycast", "params": {"bogus": 1}}]})"); });
  EXPECT_TRUE(contains(e, "bogus")) << e;

  e = errorOf([&] { parse(head + R"("panes": [{"technique": "whitted"}], "inspect": {"pane": 0, "pixel": [3]}})"); });
  EXPECT_TRUE(contains(e, "pixel must be [x, y]")) << e;
  e = errorOf([&] { parse(head + R"("panes": [{"technique": "whitted"}], "inspect": {"pane": 9, "pixel": [3, 4]}})"); });
  EXPECT_TRUE(contains(e, "pane")) << e;

  e = errorOf([&] {
    parse(head + R"("panes": [{"technique": "raycast"}], "compare": {"mode": "blend"}})");
  });
  EXPECT_TRUE(contains(e, "side-by-side, wipe, difference")) << e;

  e = errorOf([&] { parse(head + R"("panes": []})"); });
  EXPECT_TRUE(contains(e, "1 to 4 panes")) << e;

  e = errorOf([&] { parse(R"({"scene": "s.json", "panes": [{"technique": "raycast"}]})"); });
  EXPECT_TRUE(contains(e, "lightlab_preset")) << e;

  e = errorOf([&] { parse(head + R"("panes": [{"technique": "raycast"}], "pane_count": 3})"); });
  EXPECT_TRUE(contains(e, "1, 2 or 4")) << e;

  e = errorOf([&] { parse(head + R"("panes": [{"technique": "raycast"}], "colour": 1})"); });
  EXPECT_TRUE(contains(e, "colour")) << e;

  e = errorOf([&] { parse(head + R"("panes": [{"technique": "raycast", "label": "a label far too long for a hall"}]})"); });
  EXPECT_TRUE(contains(e, "1 to 24 characters")) << e;
  EXPECT_TRUE(contains(e, "p.json:1:")) << e;

  e = errorOf([&] { loadPreset("/nonexistent/preset.json"); });
  EXPECT_TRUE(contains(e, "/nonexistent/preset.json")) << e;
}

TEST(ViewPreset, EveryBundledPresetLoadsAndNamesAnExistingScene) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(std::string(LIGHTLAB_DATA_DIR) + "/presets")) {
    if (entry.path().extension() != ".json") continue;
#ifndef LIGHTLAB_HAVE_GUI
    if (entry.path().filename() == "cpu_vs_gpu.json") continue;  // names blinn-phong-gl, built with the GUI only
#endif
    const ViewPreset p = loadPreset(entry.path().string());
    EXPECT_TRUE(fs::exists(p.scene)) << entry.path() << ": " << p.scene;
    ++count;
  }
  EXPECT_GE(count, 3);
}

}  // namespace
}  // namespace ll
