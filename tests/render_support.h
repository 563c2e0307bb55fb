// A whole render in one call, for tests: scene, technique and accelerator by
// name, parameter assignments, settings. (tests/ is on the tests' include path.)
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/image.h"
#include "modules/registry.h"
#include "render/render_job.h"
#include "render/render_stats.h"
#include "scene/scene.h"

namespace ll::testing_support {

struct RenderResult {
  Image image;        // resolved without stub stripes
  RenderStats stats;
  bool anyStub = false;  // some sample went through a student stub
};

inline RenderResult renderWith(const Scene& scene, const std::string& technique, const std::string& accelerator,
                               const std::vector<std::pair<std::string, std::string>>& sets,
                               const RenderSettings& settings) {
  const AcceleratorInfo& a = findAccelerator(accelerator);
  const auto accel = buildAccelerator(a, ParamSet(a.name, a.params), scene.geometry);
  const TechniqueInfo& info = findTechnique(technique);
  ParamSet params(info.name, info.params);
  for (const auto& [k, v] : sets) params.set(k, v);
  const auto t = info.make();
  RenderJob job(scene, *accel, *t, params, settings);
  job.run();
  return {job.frame().resolve(false), job.stats(), job.frame().anyStub()};
}

// Every bundled scene: data/scenes/*.json (not the schema) and data/scenes/tests/*.json.
inline std::vector<std::string> bundledScenes() {
  namespace fs = std::filesystem;
  std::vector<std::string> scenes;
  for (const auto& e : fs::directory_iterator(std::string(LIGHTLAB_DATA_DIR) + "/scenes"))
    if (e.path().extension() == ".json" && e.path().filename() != "scene.schema.json") scenes.push_back(e.path().string());
  for (const auto& e : fs::directory_iterator(std::string(LIGHTLAB_DATA_DIR) + "/scenes/tests"))
    if (e.path().extension() == ".json") scenes.push_back(e.path().string());
  return scenes;
}

// Settings for a w x h render with `spp` samples and seed `seed`.
inline RenderSettings renderSettings(int width, int height, int spp = 1, uint64_t seed = 0) {
  RenderSettings s;
  s.width = width;
  s.height = height;
  s.spp = spp;
  s.seed = seed;
  return s;
}

}  // namespace ll::testing_support
