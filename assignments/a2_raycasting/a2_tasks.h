// Assignment 2 -- Ray casting (Appel 1968). The five functions you write.
// Each lives in its own .cpp file between the markers of its task ID; the
// technique `raycast` (raycast.cpp) calls them. Until you write one, its stub
// reports the task as missing and the task's reference (the course's solution,
// object code) answers in its place, the pixels striped, so the tasks can be
// done in any order. See README.md for the handout and the --reference switches.
#pragma once

#include "core/math.h"
#include "core/ray.h"
#include "render/tracer.h"
#include "scene/camera.h"
#include "scene/geometry.h"
#include "scene/scene.h"

namespace ll::a2 {

// A2.1 Camera rays. The primary ray through the continuous image position
// (px, py): (0,0) is the image's top-left corner, (camera.width,
// camera.height) its bottom-right, so pixel (x, y)'s centre is (x+0.5, y+0.5).
// Origin at camera.eye; direction unit length; image right is
// normalize(cross(target - eye, up)); vertical field of view camera.fovYDeg.
Ray cameraRay(const Camera& camera, float px, float py);

// A2.2 Ray-sphere. The smallest t with ray.tmin < t < ray.tmax where
// ray.origin + t * ray.dir lies on the sphere; false if there is none.
// ray.dir need not be unit length.
bool raySphere(const Ray& ray, const Sphere& sphere, float& t);

// A2.3 Ray-triangle. The t in (ray.tmin, ray.tmax) where the ray meets the
// triangle (p0, p1, p2), and the barycentric weights b1, b2 of p1 and p2
// (the hit point is (1-b1-b2) p0 + b1 p1 + b2 p2). Both faces count.
bool rayTriangle(const Ray& ray, const Vec3& p0, const Vec3& p1, const Vec3& p2, float& t, float& b1,
                 float& b2);

// A2.4 Blinn-Phong. What one light adds at a surface point, exactly as the
// lecture writes it:  kd (I/r^2) max(0, n.l) + ks (I/r^2) max(0, n.h)^p,
// with h = (v + l) / |v + l|. Directional lights have no 1/r^2 falloff
// (light.distance is infinite). The ambient term ka Ia is added by raycast.cpp.
// Each term is clamped on its own: a light just behind the surface (n.l <= 0)
// still gives the specular term while n.h > 0 -- unlike A1.4, which drops both
// terms there; the tests check the lecture's formula as written.
struct ShadingInput {
  Vec3 n;           // unit shading normal, on the viewer's side
  Vec3 v;           // unit direction from the point to the eye
  Rgb kd;           // diffuse reflectance (texture applied)
  Rgb ks;           // specular reflectance
  float shininess;  // Blinn-Phong exponent p
};
struct LightInput {
  Vec3 l;          // unit direction from the point to the light
  float distance;  // r, scene units; +infinity for directional lights
  Rgb intensity;   // I, lecture units
};
Rgb blinnPhong(const ShadingInput& surface, const LightInput& light);

// A2.5 Shadow rays. The ray that asks "is the light visible from sp?": it
// leaves sp towards the light (unit direction toLight) and must end before
// the light at `distance` (infinite for directional lights). It must not
// re-hit sp's own surface -- see offsetRayOrigin() in render/ray_offset.h.
Ray shadowRay(const SurfacePoint& sp, const Vec3& toLight, float distance);

}  // namespace ll::a2
