// Pinhole camera as the scene file states it: eye, target, up and the vertical
// field of view, plus the image resolution in pixels.
#pragma once

#include "core/math.h"
#include "core/ray.h"

namespace ll {

struct Camera {
  Vec3 eye{0.0f, 0.0f, 5.0f};
  Vec3 target{0.0f};
  Vec3 up{0.0f, 1.0f, 0.0f};
  float fovYDeg = 45.0f;  // vertical field of view, degrees, in (0, 180)
  int width = 512;        // pixels
  int height = 512;

  float aspect() const { return static_cast<float>(width) / static_cast<float>(height); }
};

// Orthonormal camera frame: forward w (towards the target), right u =
// normalize(w x up), true up v = u x w. Image x grows along u, image y
// grows against v (row 0 is the top). Precondition: up not parallel to w.
struct CameraFrame {
  Vec3 u, v, w;
  float tanHalfFovY;  // tan(fovY / 2)
  explicit CameraFrame(const Camera& c);
};

// Reference primary ray through the continuous pixel position (px, py), with
// (0,0) the top-left corner of the image and (width, height) the bottom-right;
// the centre of pixel (x, y) is (x + 0.5, y + 0.5). Direction is unit length.
Ray referenceCameraRay(const Camera& camera, const CameraFrame& frame, float px, float py);

}  // namespace ll
