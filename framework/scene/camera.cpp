// LIGHTLAB_ANSWER_FILE A2.1: the reference camera answers task A2.1, so the student
// tree holds this file as object code only (tasks/framework_answer.h).
#include "scene/camera.h"

#include "tasks/framework_answer.h"

namespace ll {

CameraFrame::CameraFrame(const Camera& c) {
  LIGHTLAB_ANSWER_GUARD("A2.1", "ll::CameraFrame (the framework's camera)");
  w = glm::normalize(c.target - c.eye);
  u = glm::normalize(glm::cross(w, c.up));
  v = glm::cross(u, w);
  tanHalfFovY = std::tan(radians(c.fovYDeg) * 0.5f);
}

Ray referenceCameraRay(const Camera& camera, const CameraFrame& f, float px, float py) {
  LIGHTLAB_ANSWER_GUARD("A2.1", "ll::referenceCameraRay (the framework's camera)");
  const float sx = (2.0f * px / static_cast<float>(camera.width) - 1.0f) * f.tanHalfFovY * camera.aspect();
  const float sy = (1.0f - 2.0f * py / static_cast<float>(camera.height)) * f.tanHalfFovY;
  Ray ray;
  ray.origin = camera.eye;
  ray.dir = glm::normalize(f.w + sx * f.u + sy * f.v);
  return ray;
}

}  // namespace ll
