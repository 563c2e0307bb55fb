// The scene as a rasterizer sees it (no GL here; shared by the CPU technique
// `blinn-phong` and its GPU twin `blinn-phong-gl`): every object as a list of
// world-space triangles (spheres tessellated), and every light as point-like
// lights (each area light as a fixed n x n grid of samples).
#pragma once

#include <utility>
#include <vector>

#include "core/math.h"
#include "scene/scene.h"

namespace ll {

struct RasterVertex {
  Vec3 position;  // world space
  Vec3 normal;    // world space, unit (the face normal when the mesh has none)
  Vec2 uv;
};

// Triangles of every object, non-indexed (3 vertices each), object by object.
struct RasterMesh {
  std::vector<RasterVertex> vertices;
  std::vector<std::pair<int, int>> ranges;  // per scene object: first vertex, vertex count
};

// Appends sphere `s` as `segments` slices x max(segments/2, 4) rings of quads (two triangles each).
void addSphere(std::vector<RasterVertex>& out, const Sphere& s, int segments);
RasterMesh buildRasterMesh(const Scene& scene, int sphereSegments);

struct RasterLight {
  enum class Kind { Point = 1, Directional = 0, AreaSample = 2 };  // values = GLSL position.w
  Kind kind = Kind::Point;
  Vec3 position{0.0f};   // point, area sample: world space; directional: unit, towards the light
  Vec3 normal{0.0f};     // area sample: unit, the emitting side
  Rgb intensity{0.0f};   // point, directional: I; area sample: Le * A / n^2 (times cos/pi per point)
};

// Point and directional lights as declared, then for each area light the
// centres of an n x n grid (n = round(sqrt(areaSamples)), at least 1) of
// scene.sampleAreaLight.
std::vector<RasterLight> rasterLights(const Scene& scene, int areaSamples);

// Near and far clip distances (world units, along the view direction) fitted
// to the scene's bounding box as seen from `camera`: the box's nearest and
// farthest depth, with a 1 % margin. A depth buffer stores about 1/z, so its
// resolution at distance z is about z^2 / near: a near plane far closer than
// the geometry (a fixed 1e-5 of the scene's reach) lets a light quad 0.5 mm
// below the Cornell box's ceiling lose to the ceiling in a tenth of its
// pixels. When the camera is inside the box, near is 1e-3 of far.
struct DepthRange {
  float near = 0.01f;
  float far = 100.0f;
};
DepthRange rasterDepthRange(const Scene& scene, const Camera& camera);

}  // namespace ll
