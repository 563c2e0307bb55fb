// The accelerator cost picture: exact counts for brute force, and a BVH that
// tests far fewer primitives than brute force on the same camera rays.
#include "render/cost_image.h"

#include <gtest/gtest.h>

#include "metrics/image_metrics.h"
#include "modules/registry.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

const std::string kScenes = std::string(LIGHTLAB_DATA_DIR) + "/scenes/";

TEST(CostImage, BruteForceTestsEveryPrimitiveForEveryPixel) {
  const Scene scene = loadScene(kScenes + "cornell_box.json");
  const auto none = buildAccelerator(findAccelerator("none"), ParamSet("none", {}), scene.geometry);
  Camera camera = scene.camera;
  camera.width = 24;
  camera.height = 16;
  const Image counts = accelCostImage(*none, camera, CostMetric::PrimitivesTested);
  ASSERT_EQ(counts.width(), 24);
  ASSERT_EQ(counts.height(), 16);
  for (const Rgb& c : counts.pixels())
    EXPECT_EQ(c, Rgb(static_cast<float>(scene.geometry.primitiveCount())));
  float used = 0.0f;
  const Image heat = costHeatmap(counts, 0.0f, &used);
  EXPECT_EQ(used, static_cast<float>(
                      scene.geometry.primitiveCount()));  // every value is the 99th percentile
  EXPECT_EQ(heat.at(3, 4), errorColormap(1.0f));
}

TEST(CostImage, TheBvhTestsFewerPrimitivesAndVisitsNodes) {
  const Scene scene = loadScene(kScenes + "bunny.json");
  const AcceleratorInfo& info = findAccelerator("bvh");
  const auto bvh = buildAccelerator(info, ParamSet("bvh", info.params), scene.geometry);
  Camera camera = scene.camera;
  camera.width = 32;
  camera.height = 32;
  const Image prims = accelCostImage(*bvh, camera, CostMetric::PrimitivesTested);
  const Image nodes = accelCostImage(*bvh, camera, CostMetric::NodesVisited);
  EXPECT_LT(prims.mean().r, 0.05f * static_cast<float>(scene.geometry.primitiveCount()));
  EXPECT_GT(nodes.mean().r, 1.0f);
  std::atomic<bool> cancel{true};
  EXPECT_TRUE(accelCostImage(*bvh, camera, CostMetric::NodesVisited, &cancel).empty());
}

}  // namespace
}  // namespace ll
