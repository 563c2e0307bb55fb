#include "gui/view_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene_limits.h"

namespace ll::gui {

namespace {
Vec3 rotate(const Vec3& v, const Vec3& axis, float angle) {
  return Vec3(glm::rotate(glm::mat4(1.0f), angle, glm::normalize(axis)) * glm::vec4(v, 0.0f));
}

// Applies `move` to a copy and keeps it only if the result is a valid camera.
template <class Move>
void moveIfValid(Camera& camera, Move&& move) {
  Camera next = camera;
  move(next);
  if (cameraIsValid(next)) camera = next;
}

// v / |v| computed without overflow or underflow of |v|^2; zero when v is zero or not finite.
Vec3 safeNormalize(const Vec3& v) {
  const float scale = largestMagnitude(v);
  if (!(scale > 0.0f) || !std::isfinite(scale)) return Vec3(0.0f);
  return glm::normalize(v / scale);
}

}  // namespace

void orbit(Camera& camera, float yaw, float pitch) {
  moveIfValid(camera, [&](Camera& c) {
    const CameraFrame frame(c);
    const Vec3 up = glm::normalize(c.up);
    Vec3 offset = c.eye - c.target;  // from target to eye
    offset = rotate(offset, up, -yaw);
    // Clamp the pitch so the view direction keeps at least 1 degree from `up`.
    const float distance = glm::length(offset);
    const float angleToUp = std::acos(std::clamp(glm::dot(offset / distance, up), -1.0f, 1.0f));
    const float margin = glm::radians(1.0f);
    const float newAngle = std::clamp(angleToUp - pitch, margin, kPi - margin);
    const Vec3 right = rotate(frame.u, up, -yaw);
    offset = rotate(offset, right, newAngle - angleToUp);
    c.eye = c.target + offset;
  });
}

void pan(Camera& camera, float dx, float dy) {
  moveIfValid(camera, [&](Camera& c) {
    const CameraFrame frame(c);
    const float distance = glm::length(c.target - c.eye);
    const float height = 2.0f * distance * frame.tanHalfFovY;
    const Vec3 shift = (-dx * frame.u - dy * frame.v) * height;
    c.eye += shift;
    c.target += shift;
  });
}

void zoom(Camera& camera, float factor) {
  const Vec3 offset = camera.eye - camera.target;
  const float distance = glm::length(offset);
  // The nearest and farthest eye a valid camera allows along this line (see cameraProblem).
  const float size = std::max({1.0f, largestMagnitude(camera.eye), largestMagnitude(camera.target)});
  const float nearest = 2e-5f * size;
  const float farthest = kMaxCameraCoordinate - largestMagnitude(camera.target);
  const float next = std::clamp(distance * std::max(factor, 0.0f), nearest, std::max(farthest, nearest));
  moveIfValid(camera, [&](Camera& c) { c.eye = c.target + offset * (next / distance); });
}

void fly(Camera& camera, Vec3 move) {
  moveIfValid(camera, [&](Camera& c) {
    const CameraFrame frame(c);
    const Vec3 shift = move.x * frame.u + move.y * frame.v + move.z * frame.w;
    c.eye += shift;
    c.target += shift;
  });
}

void frameBounds(Camera& camera, const Bounds3& bounds) {
  Vec3 dir = safeNormalize(camera.target - camera.eye);
  if (dir == Vec3(0.0f)) dir = Vec3(0.0f, 0.0f, -1.0f);
  const float radius = std::max(0.5f * bounds.diagonal(), 1e-6f);
  const float halfY = glm::radians(camera.fovYDeg) * 0.5f;
  const float halfX = std::atan(std::tan(halfY) * camera.aspect());
  const float distance = radius / std::sin(std::min(halfX, halfY));
  camera.target = bounds.center();
  camera.eye = camera.target - dir * distance;
  // Looking along up: tilt up away from the new view direction.
  if (glm::length(glm::cross(dir, safeNormalize(camera.up))) < 1e-3f)
    camera.up = std::abs(dir.y) < 0.9f ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
}

std::string cameraProblem(const Camera& camera) {
  const auto finite = [](const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  if (!finite(camera.eye) || !finite(camera.target) || !finite(camera.up) || !std::isfinite(camera.fovYDeg))
    return "a number is not finite";
  if (!withinCameraLimits(camera.eye) || !withinCameraLimits(camera.target))
    return "eye or target beyond +-1e9 scene units (overflow)";
  if (!(camera.fovYDeg > 0.0f && camera.fovYDeg < 180.0f)) return "fov y outside (0, 180)";
  const Vec3 view = camera.target - camera.eye;
  const float size = std::max({1.0f, largestMagnitude(camera.eye), largestMagnitude(camera.target)});
  if (largestMagnitude(view) < 1e-5f * size) return "eye = target";
  if (largestMagnitude(camera.up) == 0.0f) return "up is zero";
  if (glm::length(glm::cross(safeNormalize(view), safeNormalize(camera.up))) <= 1e-4f)
    return "up parallel to the view direction";
  return "";
}

bool cameraIsValid(const Camera& camera) { return cameraProblem(camera).empty(); }

}  // namespace ll::gui
