// Interactive camera moves on a scene Camera, shared by every pane of the GUI.
// World space, scene units; angles in radians. Pure functions of the camera
// (no GL, no input state), so they are unit-tested headless.
#pragma once

#include <string>

#include "core/math.h"
#include "scene/camera.h"

namespace ll::gui {

// Every move below is all or nothing: a move that would leave the camera
// invalid (see cameraProblem) leaves it as it was, so no sequence of wheel
// steps, drags or flights can reach NaN or a degenerate view.

// Turns the eye around the target: yaw about the camera's up vector, pitch
// about its right vector. Pitch stops 1 degree short of the up axis so the
// view direction never becomes parallel to `up` (the camera stays valid).
void orbit(Camera& camera, float yaw, float pitch);

// Slides eye and target together in the image plane. dx, dy are fractions of
// the visible height at the target's distance (dx > 0 moves the view right,
// dy > 0 moves it up), so a drag across the image moves the scene with it.
void pan(Camera& camera, float dx, float dy);

// Moves the eye towards the target: distance *= factor (factor > 0), within
// the limits of a valid camera (the eye stays a representable distance from
// the target, and within the scene limits).
void zoom(Camera& camera, float factor);

// Moves eye and target together by `move` in the camera frame
// (x = right, y = up, z = forward), in scene units (WASD flying).
void fly(Camera& camera, Vec3 move);

// Keeps the view direction and field of view; places the target at the
// centre of `bounds` and the eye so that the bounding sphere fills the view
// (the narrower of the vertical and horizontal fields of view). If the view
// direction cannot be computed (eye = target), looks along -z.
// Precondition: bounds not empty and within the scene limits.
void frameBounds(Camera& camera, const Bounds3& bounds);

// Why a camera cannot be used, in a few words, or "" when it can: every number
// finite, eye and target within +-kMaxCameraCoordinate, the eye a distance from
// the target that float arithmetic resolves (at least 1e-5 of their size),
// up not parallel to the view direction, 0 < fovY < 180.
std::string cameraProblem(const Camera& camera);
bool cameraIsValid(const Camera& camera);

}  // namespace ll::gui
