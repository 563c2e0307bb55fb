// `lightlab trace -t raycast`'s ray tree: the camera ray and one shadow ray per light sample, each
// light's Blinn-Phong term as its shadow ray's share, emission and ambient as the camera ray's; the
// shares add up to the pixel, which is the render's at that pixel.
#include <gtest/gtest.h>

#include "modules/registry.h"
#include "render_support.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

RayTree raycastTree(const Scene& scene, int x, int y, int width, int height, const std::string& lightSamples) {
  const AcceleratorInfo& a = findAccelerator("bvh");
  const auto accel = buildAccelerator(a, ParamSet(a.name, a.params), scene.geometry);
  const TechniqueInfo& info = findTechnique("raycast");
  ParamSet params(info.name, info.params);
  params.set("light_samples", lightSamples);
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  const RenderContext ctx{scene, *accel, params, settings, nullptr};
  const auto technique = info.make();
  technique->prepare(ctx);
  const auto tree = technique->rayTree(ctx, Vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
  EXPECT_TRUE(tree.has_value());
  return tree.value_or(RayTree{});
}

Rgb sumOfShares(const RayTree& tree) {
  Rgb sum(0.0f);
  for (const RayTreeNode& n : tree.nodes) sum += n.contribution;
  return sum;
}

TEST(RaycastRayTree, APointLitSphereIsItsAmbientPlusTheLightsTerm) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/tests/sphere_point_light.json");
  const RayTree tree = raycastTree(scene, 31, 31, 64, 64, "1");
  ASSERT_EQ(tree.nodes.size(), 2u);  // the camera ray and the point light's shadow ray
  EXPECT_EQ(tree.nodes[0].kind, RayKind::Camera);
  EXPECT_TRUE(tree.nodes[0].hit);
  EXPECT_EQ(tree.nodes[1].kind, RayKind::Shadow);
  EXPECT_EQ(tree.nodes[1].parent, 0);
  EXPECT_EQ(tree.nodes[1].shadowTransmittance, Rgb(1.0f));  // nothing stands between a convex sphere and its light
  EXPECT_GT(maxComponent(tree.nodes[1].contribution), maxComponent(tree.nodes[0].contribution));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sumOfShares(tree)[c], tree.pixel[c], 1e-6f);
  // The pixel is the render's there (a smooth spot of the sphere: the render's 16 samples spread over
  // the pixel differ from its centre by far less than 1 %).
  RenderSettings s;
  s.width = 64;
  s.height = 64;
  s.spp = 16;
  const Image image = testing_support::renderWith(scene, "raycast", "bvh", {{"light_samples", "1"}}, s).image;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.at(31, 31)[c], tree.pixel[c], 0.01f * tree.pixel[c]);
}

TEST(RaycastRayTree, AnAreaLightGivesOneShadowRayPerSampleAndTheSharesAddUp) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/cornell_box.json");
  // The floor in front of the blocks, lit by the ceiling's lamp.
  const RayTree tree = raycastTree(scene, 256, 480, 512, 512, "4");
  ASSERT_FALSE(tree.nodes.empty());
  ASSERT_TRUE(tree.nodes[0].hit);
  int shadows = 0;
  for (const RayTreeNode& n : tree.nodes) shadows += n.kind == RayKind::Shadow;
  EXPECT_EQ(shadows, 4);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sumOfShares(tree)[c], tree.pixel[c], 1e-6f * (1.0f + tree.pixel[c]));
}

}  // namespace
}  // namespace ll
