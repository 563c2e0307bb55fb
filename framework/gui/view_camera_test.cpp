// The GUI's camera moves: exact geometric properties, and the camera always
// stays valid (never looking along `up`).
#include "gui/view_camera.h"

#include <cmath>

#include <gtest/gtest.h>

namespace ll::gui {
namespace {

Camera lookingDownZ() {
  Camera c;
  c.eye = Vec3(0, 0, 10);
  c.target = Vec3(0, 0, 0);
  c.up = Vec3(0, 1, 0);
  c.fovYDeg = 60.0f;
  c.width = 400;
  c.height = 200;
  return c;
}

float distance(const Camera& c) {
  return glm::length(c.eye - c.target);
}

TEST(ViewCamera, OrbitKeepsTheDistanceAndTheTarget) {
  Camera c = lookingDownZ();
  orbit(c, 0.7f, 0.3f);
  EXPECT_NEAR(distance(c), 10.0f, 1e-4f);
  EXPECT_EQ(c.target, Vec3(0.0f));
  EXPECT_TRUE(cameraIsValid(c));
}

TEST(ViewCamera, YawTurnsAboutUpAndAFullTurnReturns) {
  Camera c = lookingDownZ();
  orbit(c, kPi / 2, 0.0f);
  EXPECT_NEAR(c.eye.y, 0.0f, 1e-4f);  // stays in the horizontal plane
  EXPECT_NEAR(std::abs(c.eye.x), 10.0f, 1e-4f);
  orbit(c, kPi / 2, 0.0f);
  orbit(c, kPi, 0.0f);
  EXPECT_NEAR(c.eye.x, 0.0f, 1e-3f);
  EXPECT_NEAR(c.eye.z, 10.0f, 1e-3f);
}

TEST(ViewCamera, PositivePitchRaisesTheEyeAndStopsShortOfThePole) {
  Camera c = lookingDownZ();
  orbit(c, 0.0f, 0.5f);
  EXPECT_NEAR(c.eye.y, 10.0f * std::sin(0.5f), 1e-3f);
  orbit(c, 0.0f, 100.0f);  // far past the pole: clamped 1 degree short
  EXPECT_NEAR(c.eye.y, 10.0f * std::cos(glm::radians(1.0f)), 1e-3f);
  EXPECT_TRUE(cameraIsValid(c));
  orbit(c, 0.0f, -100.0f);
  EXPECT_NEAR(c.eye.y, -10.0f * std::cos(glm::radians(1.0f)), 1e-3f);
  EXPECT_TRUE(cameraIsValid(c));
}

TEST(ViewCamera, PanMovesEyeAndTargetTogetherInTheImagePlane) {
  Camera c = lookingDownZ();
  pan(c, 0.5f, 0.25f);
  // Visible height at the target: 2 * 10 * tan(30 deg).
  const float height = 20.0f * std::tan(glm::radians(30.0f));
  EXPECT_NEAR(c.target.x, -0.5f * height, 1e-4f);  // the view moves right: the scene shifts left
  EXPECT_NEAR(c.target.y, -0.25f * height, 1e-4f);
  EXPECT_NEAR(c.eye.z - c.target.z, 10.0f, 1e-4f);
  EXPECT_NEAR(distance(c), 10.0f, 1e-4f);
}

TEST(ViewCamera, ZoomScalesTheDistanceAndNeverReachesTheTarget) {
  Camera c = lookingDownZ();
  zoom(c, 0.5f);
  EXPECT_NEAR(distance(c), 5.0f, 1e-5f);
  zoom(c, 0.0f);
  EXPECT_GT(distance(c), 0.0f);
  EXPECT_TRUE(cameraIsValid(c));
}

// About 620 wheel steps once made the eye NaN (the distance underflowed to 0); Reset was the only way back.
TEST(ViewCamera, TenThousandWheelStepsEitherWayLeaveAValidCamera) {
  for (const float step : {0.85f, 1.0f / 0.85f}) {
    Camera c = lookingDownZ();
    for (int i = 0; i < 10000; ++i) {
      zoom(c, step);
      ASSERT_TRUE(cameraIsValid(c)) << "step " << i << ": " << cameraProblem(c);
    }
    // The eye can come back: zooming the other way works from where it stopped.
    const float stopped = distance(c);
    zoom(c, 1.0f / step);
    EXPECT_NE(distance(c), stopped);
    EXPECT_TRUE(cameraIsValid(c));
  }
  Camera c = lookingDownZ();
  for (int i = 0; i < 10000; ++i) zoom(c, 0.85f);
  EXPECT_GT(distance(c), 0.0f);
  EXPECT_LT(distance(c), 1e-3f) << "the wheel still zooms close to the target";
}

TEST(ViewCamera, FlyingAndPanningStopAtTheSceneLimits) {
  Camera c = lookingDownZ();
  for (int i = 0; i < 10000; ++i) {
    fly(c, Vec3(0, 0, -1e7f));  // backwards, 1e7 units a frame
    pan(c, 3.0f, 0.0f);
  }
  EXPECT_TRUE(cameraIsValid(c)) << cameraProblem(c);
  EXPECT_LE(std::abs(c.eye.z), 1e9f);
  fly(c, Vec3(std::nanf(""), 0, 0));
  EXPECT_TRUE(cameraIsValid(c)) << "a NaN move is not applied";
}

// Frame scene after an eye at 1e38 (typed) put the eye on the target: |target - eye|^2 overflowed.
TEST(ViewCamera, FrameSceneRecoversFromAFarOrDegenerateEye) {
  Bounds3 b;
  b.extend(Vec3(-1, -1, -1));
  b.extend(Vec3(1, 1, 1));
  for (const Vec3 eye : {Vec3(1e38f, 0, 0), Vec3(0.0f), Vec3(0, 1e30f, 0)}) {
    Camera c = lookingDownZ();
    c.eye = eye;
    frameBounds(c, b);
    EXPECT_TRUE(cameraIsValid(c)) << cameraProblem(c) << " after an eye at " << eye.x << " " << eye.y;
    EXPECT_GT(distance(c), 1.0f);
  }
}

TEST(ViewCamera, TypedValuesBeyondTheSceneLimitsAreOverflow) {
  Camera c = lookingDownZ();
  c.eye.x = 1e38f;
  EXPECT_EQ(cameraProblem(c), "eye or target beyond +-1e9 scene units (overflow)");
  c = lookingDownZ();
  c.target = c.eye + Vec3(0, 0, 1e-9f);
  EXPECT_EQ(cameraProblem(c), "eye = target");
}

TEST(ViewCamera, FlyMovesAlongTheCameraFrame) {
  Camera c = lookingDownZ();
  fly(c, Vec3(0, 0, 2));  // forward = towards -z
  EXPECT_NEAR(c.eye.z, 8.0f, 1e-5f);
  EXPECT_NEAR(c.target.z, -2.0f, 1e-5f);
  fly(c, Vec3(1, 0, 0));  // right = +x
  EXPECT_NEAR(c.eye.x, 1.0f, 1e-5f);
}

TEST(ViewCamera, FrameBoundsPutsEveryCornerInsideTheImage) {
  Camera c = lookingDownZ();
  orbit(c, 0.4f, 0.3f);
  Bounds3 b;
  b.extend(Vec3(100, 50, -20));
  b.extend(Vec3(140, 60, 30));
  frameBounds(c, b);
  EXPECT_NEAR(glm::length(c.target - b.center()), 0.0f, 1e-3f);
  const CameraFrame f(c);
  for (int i = 0; i < 8; ++i) {
    const Vec3 p((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                 (i & 4) ? b.max.z : b.min.z);
    const Vec3 d = p - c.eye;
    const float z = glm::dot(d, f.w);
    ASSERT_GT(z, 0.0f);
    EXPECT_LE(std::abs(glm::dot(d, f.v)) / z, f.tanHalfFovY * 1.0001f);
    EXPECT_LE(std::abs(glm::dot(d, f.u)) / z, f.tanHalfFovY * c.aspect() * 1.0001f);
  }
}

TEST(ViewCamera, InvalidCamerasAreRecognised) {
  Camera c = lookingDownZ();
  EXPECT_TRUE(cameraIsValid(c));
  c.up = Vec3(0, 0, 1);  // parallel to the view direction
  EXPECT_FALSE(cameraIsValid(c));
  c = lookingDownZ();
  c.target = c.eye;
  EXPECT_FALSE(cameraIsValid(c));
  c = lookingDownZ();
  c.eye.x = std::nanf("");
  EXPECT_FALSE(cameraIsValid(c));
  c = lookingDownZ();
  c.fovYDeg = 180.0f;
  EXPECT_FALSE(cameraIsValid(c));
}

}  // namespace
}  // namespace ll::gui
