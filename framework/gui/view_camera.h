// Interactive camera moves on a scene Camera, shared by every pane of the GUI.
// World space, scene units; angles in radians. Pure functions of the camera
// (no GL, no input state), so they are unit-tested headless.
#pragma once

#include "core/math.h"
#include "scene/camera.h"

namespace ll::gui {

// Turns the eye around the target: yaw about the camera's up vector, pitch
// about its right vector. Pitch stops 1 degree short of the up axis so the
// view direction never becomes parallel to `up` (the camera stays valid).
void orbit(Camera& camera, float yaw, float pitch);

// Slides eye and target together in the image plane. dx, dy are fractions of
// the visible height at the target's distance (dx > 0 moves the view right,
// dy > 0 moves it up), so a drag across the image moves the scene with it.
void pan(Camera& camera, float dx, float dy);

// Moves the eye towards the target: distance *= factor (factor > 0). The
// distance never drops below 1e-4 of its value, so the target stays ahead.
void zoom(Camera& camera, float factor);

// Moves eye and target together by `move` in the camera frame
// (x = right, y = up, z = forward), in scene units (WASD flying).
void fly(Camera& camera, Vec3 move);

// Keeps the view direction and field of view; places the target at the
// centre of `bounds` and the eye so that the bounding sphere fills the view
// (the narrower of the vertical and horizontal fields of view).
// Precondition: bounds not empty.
void frameBounds(Camera& camera, const Bounds3& bounds);

// A camera is usable when eye != target, up is not parallel to the view
// direction and every number is finite with 0 < fovY < 180.
bool cameraIsValid(const Camera& camera);

}  // namespace ll::gui
