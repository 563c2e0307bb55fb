// Projection for the structure overlay agrees with the camera rays.
#include "gui/structure_overlay.h"

#include <gtest/gtest.h>

namespace ll::gui {
namespace {

TEST(StructureOverlay, ProjectionInvertsTheCameraRay) {
  Camera c;
  c.eye = Vec3(1, 2, 10);
  c.target = Vec3(0, 1, 0);
  c.fovYDeg = 50.0f;
  c.width = 320;
  c.height = 200;
  float px = 0, py = 0;
  ASSERT_TRUE(projectToImage(c, c.target, px, py));
  EXPECT_NEAR(px, 160.0f, 1e-3f);
  EXPECT_NEAR(py, 100.0f, 1e-3f);
  const CameraFrame f(c);
  for (const Vec2 pixel : {Vec2(10.5f, 20.5f), Vec2(300.0f, 190.0f), Vec2(160.0f, 0.0f)}) {
    const Ray r = referenceCameraRay(c, f, pixel.x, pixel.y);
    ASSERT_TRUE(projectToImage(c, r.origin + 7.0f * r.dir, px, py));
    EXPECT_NEAR(px, pixel.x, 1e-2f);
    EXPECT_NEAR(py, pixel.y, 1e-2f);
  }
  EXPECT_FALSE(projectToImage(c, c.eye - (c.target - c.eye), px, py));  // behind the eye
}

}  // namespace
}  // namespace ll::gui
