// The assignments' task scenes against their reference images: every
// data/references/<assignment>/references.json lists renders (scene,
// technique parameters, size) with named tolerances; each render must meet
// them, and every listed known mistake must miss them -- the tolerances
// pass a correct solution and catch a wrong one.
// LIGHTLAB_UPDATE_REFERENCES=1 rewrites the reference images instead.
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/image.h"
#include "metrics/image_metrics.h"
#include "modules/registry.h"
#include "render/render_job.h"
#include "scene/json_document.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

namespace fs = std::filesystem;

Image renderEntry(const nlohmann::json& entry, const nlohmann::json& set, const std::string& techniqueName) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/" + entry.at("scene").get<std::string>());
  const AcceleratorInfo& a = findAccelerator("none");
  const auto accel = buildAccelerator(a, ParamSet(a.name, a.params), scene.geometry);
  const TechniqueInfo& t = findTechnique(techniqueName);
  ParamSet params(t.name, t.params);
  for (const auto& [name, value] : set.items()) params.set(name, value.get<std::string>());
  RenderSettings settings;
  settings.width = entry.at("size").at(0).get<int>();
  settings.height = entry.at("size").at(1).get<int>();
  const auto technique = t.make();
  RenderJob job(scene, *accel, *technique, params, settings);
  job.run();
  EXPECT_EQ(job.stats().work.nonFinite, 0u);
  return job.frame().resolve(false);
}

// Whether `error` meets every tolerance of `entry`; the values in `report`.
bool withinTolerance(const ImageError& error, const nlohmann::json& entry, std::string& report) {
  bool ok = true;
  for (const auto& tol : entry.at("tolerance")) {
    const std::string metric = tol.at("metric").get<std::string>();
    const double value = metricValue(error, metric);
    const bool pass = tol.contains("max") ? value <= tol.at("max").get<double>() : value >= tol.at("min").get<double>();
    report += metric + " " + std::to_string(value) + (pass ? " ok; " : " OUT; ");
    ok = ok && pass;
  }
  return ok;
}

void checkManifest(const std::string& dir) {
  const JsonDocument doc = JsonDocument::load(dir + "references.json");
  const std::string technique = doc.root().at("technique").get<std::string>();
  const bool update = std::getenv("LIGHTLAB_UPDATE_REFERENCES") != nullptr;
  for (const auto& entry : doc.root().at("references")) {
    const std::string path = dir + entry.at("image").get<std::string>();
    SCOPED_TRACE(path);
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
      EXPECT_FALSE(withinTolerance(compareImages(renderEntry(entry, mistake.at("set"), technique), reference), entry,
                                   mistakeReport))
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
