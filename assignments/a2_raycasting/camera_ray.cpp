// A2.1 Camera rays.
#include "a2_tasks.h"
#include "render/student_task.h"

namespace ll::a2 {

Ray cameraRay(const Camera& camera, float px, float py) {
#if LIGHTLAB_SOLUTION  // A2.1
  // Camera frame: w towards the target, u to the image's right, v up.
  const Vec3 w = glm::normalize(camera.target - camera.eye);
  const Vec3 u = glm::normalize(glm::cross(w, camera.up));
  const Vec3 v = glm::cross(u, w);
  // Image plane at distance 1: half-height tan(fov/2), half-width aspect times that.
  const float halfHeight = std::tan(radians(camera.fovYDeg) * 0.5f);
  const float halfWidth = halfHeight * static_cast<float>(camera.width) / static_cast<float>(camera.height);
  const float sx = (2.0f * px / static_cast<float>(camera.width) - 1.0f) * halfWidth;
  const float sy = (1.0f - 2.0f * py / static_cast<float>(camera.height)) * halfHeight;
  Ray ray;
  ray.origin = camera.eye;
  ray.dir = glm::normalize(w + sx * u + sy * v);
  return ray;
#else
  // Your A2.1 here (see its comment in a2_tasks.h), then delete the line below.
  (void)camera;
  (void)px;
  (void)py;
  LIGHTLAB_TODO("A2.1", "camera rays (assignments/a2_raycasting/camera_ray.cpp)");
  return Ray{};
#endif
}

}  // namespace ll::a2
