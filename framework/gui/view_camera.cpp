#include "gui/view_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace ll::gui {

namespace {
Vec3 rotate(const Vec3& v, const Vec3& axis, float angle) {
  return Vec3(glm::rotate(glm::mat4(1.0f), angle, glm::normalize(axis)) * glm::vec4(v, 0.0f));
}
}  // namespace

void orbit(Camera& camera, float yaw, float pitch) {
  const CameraFrame frame(camera);
  const Vec3 up = glm::normalize(camera.up);
  Vec3 offset = camera.eye - camera.target;  // from target to eye
  offset = rotate(offset, up, -yaw);
  // Clamp the pitch so the view direction keeps at least 1 degree from `up`.
  const float distance = glm::length(offset);
  const float angleToUp = std::acos(std::clamp(glm::dot(offset / distance, up), -1.0f, 1.0f));
  const float margin = glm::radians(1.0f);
  const float newAngle = std::clamp(angleToUp - pitch, margin, kPi - margin);
  const Vec3 right = rotate(frame.u, up, -yaw);
  offset = rotate(offset, right, newAngle - angleToUp);
  camera.eye = camera.target + offset;
}

void pan(Camera& camera, float dx, float dy) {
  const CameraFrame frame(camera);
  const float distance = glm::length(camera.target - camera.eye);
  const float height = 2.0f * distance * frame.tanHalfFovY;
  const Vec3 shift = (-dx * frame.u - dy * frame.v) * height;
  camera.eye += shift;
  camera.target += shift;
}

void zoom(Camera& camera, float factor) {
  const Vec3 offset = camera.eye - camera.target;
  const float distance = glm::length(offset);
  const float next = std::max(distance * std::max(factor, 1e-4f), distance * 1e-4f);
  camera.eye = camera.target + offset * (next / distance);
}

void fly(Camera& camera, Vec3 move) {
  const CameraFrame frame(camera);
  const Vec3 shift = move.x * frame.u + move.y * frame.v + move.z * frame.w;
  camera.eye += shift;
  camera.target += shift;
}

void frameBounds(Camera& camera, const Bounds3& bounds) {
  const Vec3 dir = glm::normalize(camera.target - camera.eye);
  const float radius = std::max(0.5f * bounds.diagonal(), 1e-6f);
  const float halfY = glm::radians(camera.fovYDeg) * 0.5f;
  const float halfX = std::atan(std::tan(halfY) * camera.aspect());
  const float distance = radius / std::sin(std::min(halfX, halfY));
  camera.target = bounds.center();
  camera.eye = camera.target - dir * distance;
}

bool cameraIsValid(const Camera& camera) {
  const Vec3 view = camera.target - camera.eye;
  const auto finite = [](const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  if (!finite(camera.eye) || !finite(camera.target) || !finite(camera.up)) return false;
  if (!(camera.fovYDeg > 0.0f && camera.fovYDeg < 180.0f)) return false;
  if (glm::length(view) <= 0.0f || glm::length(camera.up) <= 0.0f) return false;
  return glm::length(glm::cross(glm::normalize(view), glm::normalize(camera.up))) > 1e-4f;
}

}  // namespace ll::gui
