// The assignments' task scenes against their reference images: every
// data/references/<assignment>/references.json lists renders (scene,
// technique parameters, size) with named tolerances; each render must meet
// them, and every listed known mistake must miss them -- the tolerances
// pass a correct solution and catch a wrong one.
// LIGHTLAB_UPDATE_REFERENCES=1 rewrites the reference images instead (=a6: only data/references/a6).
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/image.h"
#include "grading/tolerance.h"
#include "metrics/image_metrics.h"
#include "metrics/pixel_ztest.h"
#include "modules/registry.h"
#include "metrics/pixel_statistics.h"
#include "render/render_job.h"
#include "scene/json_document.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

namespace fs = std::filesystem;

Image renderEntry(const nlohmann::json& entry, const nlohmann::json& set, const std::string& techniqueName,
                  unsigned seed = 1) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/" + entry.at("scene").get<std::string>());
  const AcceleratorInfo& a = findAccelerator("none");
  const auto accel = buildAccelerator(a, ParamSet(a.name, a.params), scene.geometry);
  const TechniqueInfo& t = findTechnique(techniqueName);
  ParamSet params(t.name, t.params);
  for (const auto& [name, value] : set.items()) params.set(name, value.get<std::string>());
  RenderSettings settings;
  settings.width = entry.at("size").at(0).get<int>();
  settings.height = entry.at("size").at(1).get<int>();
  settings.seed = seed;
  settings.spp = entry.value("spp", 1);
  const auto technique = t.make();
  RenderJob job(scene, *accel, *technique, params, settings);
  job.run();
  EXPECT_EQ(job.stats().work.nonFinite, 0u);
  return job.frame().resolve(false);
}

// Whether `error` meets every tolerance of `entry`; the values in `report`.
bool withinTolerance(const ImageError& error, const nlohmann::json& entry, std::string& report) {
  bool ok = true;
  for (const grading::ToleranceCheck& c : grading::checkTolerances(error, entry.at("tolerance"))) {
    report += c.metric + " " + std::to_string(c.value) + (c.passed ? " ok; " : " OUT; ");
    ok = ok && c.passed;
  }
  return ok;
}

// A Monte Carlo entry ("variance" names its variance image): the reference is
// the mean of `renders` renders with seeds 1000, 1001, ...; the variance image
// holds the variance of one render's pixel, times (1 + 1/renders) for the
// mean's own noise. A render with any other seed passes the per-pixel Z-test;
// each catch (parameter changes, or "scale": a brightness error) fails it.
void checkStatistical(const std::string& dir, const nlohmann::json& entry, const std::string& technique, bool update) {
  const std::string meanPath = dir + entry.at("image").get<std::string>();
  const std::string variancePath = dir + entry.at("variance").get<std::string>();
  if (update) {
    const int n = entry.at("renders").get<int>();
    std::vector<Image> renders;
    for (int k = 0; k < n; ++k) renders.push_back(renderEntry(entry, entry.at("set"), technique, 1000u + static_cast<unsigned>(k)));
    PixelStatistics stats = pixelStatistics(renders);
    for (Rgb& v : stats.variance.pixels()) v *= 1.0f + 1.0f / static_cast<float>(n);  // the mean's own noise
    saveImage(stats.mean, meanPath);
    saveImage(stats.variance, variancePath);
    return;
  }
  const Image mean = loadImage(meanPath), variance = loadImage(variancePath);
  const ZTestSettings z = grading::zTestSettings(entry);
  for (const unsigned seed : {1u, 2u, 3u}) {
    const ZTestResult r = pixelZTest(renderEntry(entry, entry.at("set"), technique, seed), mean, variance, z);
    EXPECT_TRUE(r.passed) << "seed " << seed << ": " << r.rejected << " pixels rejected, worst p " << r.minPValue
                          << " at " << r.worstX << "," << r.worstY << " (z " << r.worstZ << ")";
    std::cout << "[ reference ] " << entry.at("image").get<std::string>() << " seed " << seed << ": min p "
              << r.minPValue << " (level " << r.correctedAlpha << ")\n";
  }
  for (const auto& mistake : entry.at("catches")) {
    Image wrong = renderEntry(entry, mistake.value("set", entry.at("set")), technique, 7);
    const float scale = mistake.value("scale", 1.0f);
    for (Rgb& p : wrong.pixels()) p *= scale;
    const ZTestResult r = pixelZTest(wrong, mean, variance, z);
    EXPECT_FALSE(r.passed) << "the Z-test does not catch: " << mistake.at("why").get<std::string>();
    std::cout << "[ reference ] " << entry.at("image").get<std::string>() << " mistake '"
              << mistake.at("why").get<std::string>() << "': " << r.rejected << " pixels rejected, min p " << r.minPValue
              << "\n";
  }
}

void checkManifest(const std::string& dir) {
  const JsonDocument doc = JsonDocument::load(dir + "references.json");
  const std::string technique = doc.root().at("technique").get<std::string>();
  // LIGHTLAB_UPDATE_REFERENCES=1 rewrites every folder's images, =a6 (a folder's name) only that folder's.
  const char* updateWhat = std::getenv("LIGHTLAB_UPDATE_REFERENCES");
  const std::string folder = std::filesystem::path(dir).parent_path().filename().string();
  const bool update = updateWhat != nullptr && (std::string(updateWhat) == "1" || folder == updateWhat);
  for (const auto& entry : doc.root().at("references")) {
    const std::string path = dir + entry.at("image").get<std::string>();
    SCOPED_TRACE(path);
    if (entry.contains("variance")) {
      checkStatistical(dir, entry, technique, update);
      continue;
    }
    const Image image = renderEntry(entry, entry.at("set"), technique);
    if (update) {
      saveImage(image, path);
      continue;
    }
    const Image reference = loadImage(path);
    std::string report;
    EXPECT_TRUE(withinTolerance(compareImages(image, reference), entry, report)) << report;
    for (const auto& mistake : entry.at("catches")) {
      std::string mistakeReport;
      Image wrong = renderEntry(entry, mistake.value("set", entry.at("set")), technique);
      for (Rgb& p : wrong.pixels()) p *= mistake.value("scale", 1.0f);
      EXPECT_FALSE(withinTolerance(compareImages(wrong, reference), entry, mistakeReport))
          << "the tolerances do not catch: " << mistake.at("why").get<std::string>() << " (" << mistakeReport << ")";
      std::cout << "[ reference ] " << entry.at("image").get<std::string>() << ": " << report << " mistake '"
                << mistake.at("why").get<std::string>() << "': " << mistakeReport << "\n";
    }
  }
}

TEST(ReferenceImages, TaskScenesMatchTheirReferencesAndKnownMistakesDoNot) {
  int manifests = 0;
  for (const auto& e : fs::directory_iterator(std::string(LIGHTLAB_DATA_DIR) + "/references")) {
    if (!fs::exists(e.path() / "references.json")) continue;
    SCOPED_TRACE(e.path().string());
    checkManifest(e.path().string() + "/");
    ++manifests;
  }
  EXPECT_GE(manifests, 2);
}

}  // namespace
}  // namespace ll
