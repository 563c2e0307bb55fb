// The scene model every technique reads: camera, materials, lights, objects
// and their world-space primitives, plus the effects the content calls for.
#pragma once

#include <string>
#include <vector>

#include "core/math.h"
#include "core/ray.h"
#include "scene/camera.h"
#include "scene/effects.h"
#include "scene/environment.h"
#include "scene/geometry.h"
#include "scene/material.h"

namespace ll {

struct Light {
  enum class Type { Point, Directional };
  Type type = Type::Point;
  Vec3 position{0.0f};                   // point lights, world space
  Vec3 direction{0.0f, -1.0f, 0.0f};     // directional lights: unit, the way light travels
  Rgb intensity{1.0f};                   // lecture units: diffuse radiance = kd * I * cos / r^2
  // Whether anything can stand between this light and a surface it lights
  // (set by Scene::finalize): if not, techniques cast no shadow rays for it.
  bool canBeOccluded = true;
};

struct SceneObject {
  std::string name;
  std::string type;   // sphere, quad, polygon, triangles, mesh
  uint32_t material = 0;
  uint32_t firstPrim = 0, primCount = 0;  // contiguous range of primitive ids
};

// An emissive object sampled by area: its primitives and their area CDF.
struct AreaLight {
  uint32_t object = 0;
  std::vector<uint32_t> prims;
  std::vector<float> cdf;  // cumulative area, last entry = area
  float area = 0.0f;       // scene units^2
  Rgb emission{0.0f};      // radiance
  bool canBeOccluded = true;  // see Light::canBeOccluded
};

// A point sampled on an area light, with density 1/area (w.r.t. area).
struct LightPoint {
  Vec3 position;
  Vec3 normal;  // unit, the emitting side
  Rgb emission;
};

// Everything a shader needs about a hit point.
struct SurfacePoint {
  Vec3 position;
  Vec3 geometricNormal;  // unit, as the primitive is wound (spheres: outward)
  Vec3 shadingNormal;    // unit, interpolated; same side as geometricNormal
  Vec2 uv;
  uint32_t prim = Hit::kNone;
  uint32_t object = 0;
  const Material* material = nullptr;
};

class Scene {
 public:
  std::string path;  // file it was loaded from, for messages
  Camera camera;
  // The sky: what a ray that leaves the scene sees, and (for the path tracer) a light.
  Environment environment;
  Rgb background{0.0f};  // environment.average(): a flat stand-in where a technique cannot look the sky up
  Rgb ambient{0.0f};  // Ia of the lecture's ambient term (local techniques only)
  std::vector<Material> materials;
  std::vector<Light> lights;
  std::vector<SceneObject> objects;
  Geometry geometry;
  std::vector<AreaLight> areaLights;
  EffectSet effects;
  // Some object's material has a mirror or a transmission term (the local model's fields, so rough metals and
  // rough glass count by their specular limit): what Whitted's secondary rays and filtered shadow rays need.
  bool hasMirrors = false, hasTransmission = false;

  // Fills areaLights, effects and the flags above from the content; loaders call it last.
  void finalize();

  SurfacePoint surfacePoint(const Ray& ray, const Hit& hit) const;
  LightPoint sampleAreaLight(const AreaLight& light, Vec2 u) const;
  const Material& materialOf(uint32_t prim) const {
    return materials[objects[geometry.objectOf(prim)].material];
  }
};

}  // namespace ll
