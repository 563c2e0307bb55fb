// Framework helpers of the Whitted ray tracer (assignment 3): what the
// recursion in radiance() (A3.4) builds on -- intersection with the
// refractive indices of the media on both sides, emitted and local
// (Blinn-Phong with shadow rays) radiance, Fresnel, and tracing a child ray
// with its weight. Also records the ray tree for the inspector.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "a3_tasks.h"
#include "core/rng.h"
#include "render/media.h"
#include "render/ray_tree.h"
#include "render/tracer.h"
#include "scene/scene.h"

namespace ll::a3 {

// The state of the path a ray belongs to.
struct PathState {
  int depth = 0;          // 0 = camera ray
  Rgb throughput{1.0f};   // weight of this ray's radiance in the pixel
  Media media;            // where the ray travels
  RayKind kind = RayKind::Camera;
  int node = -1;          // its node in the ray tree being recorded, or -1
  bool refracted = false;  // a refraction ray is among its ancestors (or it is one)
};

// A hit as the recursion sees it.
struct Surface {
  SurfacePoint sp;      // position, uv, material (sp.shadingNormal as wound)
  Vec3 d{0.0f};         // unit incoming direction
  Vec3 n{0.0f};         // unit shading normal, turned to the incoming side (d.n <= 0)
  Vec3 ng{0.0f};        // unit geometric normal, turned to the incoming side
  float t = 0.0f;       // distance travelled (scene units)
  bool entering = false;  // arrived on the front side of the surface
  float n1 = 1.0f;        // refractive index of the medium the ray came through
  float n2 = 1.0f;        // refractive index behind the surface
  Media mediaBehind;      // the media a transmitted ray travels in
  // Beer-Lambert: exp(-sigma t) of the medium the ray came through; the
  // radiance returned along the ray is multiplied by it.
  Rgb absorption{1.0f};
  PathState path;  // the ray's state, throughput already times `absorption`
  const Material& material() const { return *sp.material; }
};

struct WhittedSettings {
  int maxDepth = 5;              // deepest ray traced (camera ray = 0)
  float minThroughput = 1e-3f;   // rays weighing less in the pixel are not traced
  bool schlick = false;          // Schlick's approximation instead of the exact Fresnel equations
  int lightSamples = 16;         // shadow rays per area light
  bool filteredShadows = true;   // shadow rays pass through transmissive surfaces, tinted and absorbed
  // --set effects=measured: light-path classes left out, their rays not traced (trace() returns black):
  // refraction rays (the refraction class), and reflection rays not below a refraction (mirror-reflection).
  bool skipRefraction = false;
  bool skipMirrorReflection = false;
};

// Schlick's approximation of the unpolarised Fresnel reflectance (framework
// code, to compare with A3.3): R0 + (1 - R0)(1 - cos)^5 with the cosine on the
// optically thinner side; 1 under total internal reflection.
float fresnelSchlick(float cosI, float n1, float n2);

class WhittedTracer {
 public:
  // `rng` draws the area-light samples; `tree` (may be null) records the rays.
  WhittedTracer(const Scene& scene, const Tracer& tracer, const WhittedSettings& settings, Rng& rng,
                RayTree* tree = nullptr);

  int maxDepth() const { return settings_.maxDepth; }
  float minThroughput() const { return settings_.minThroughput; }

  // The closest hit of `ray` (unit direction), counted as a ray of path.kind.
  std::optional<Surface> intersect(const Ray& ray, const PathState& path) const;
  // What `ray` sees when it leaves the scene: the sky in its direction.
  Rgb background(const Ray& ray) const { return scene_.environment.radiance(glm::normalize(ray.dir)); }
  // Emission of the surface towards the ray (emitters emit on their front side).
  Rgb emitted(const Surface& s) const;
  // The lecture's local term: ka Ia + sum over lights of kd (I/r^2) max(0, n.l)
  // + ks (I/r^2) max(0, n.h)^p, each light only if its shadow ray gets through.
  Rgb local(const Surface& s) const;
  // Fresnel reflectance F at a dielectric hit (A3.3, or Schlick's if chosen); 1 under total internal reflection.
  float fresnel(const Surface& s) const;
  // weight x the radiance arriving along the child ray `ray` of `from`
  // (radiance() one level deeper). A Refraction ray travels in
  // from.mediaBehind, any other in from.path.media. Black, and no ray
  // traced, for a ray of a class the settings skip.
  Rgb trace(const Ray& ray, RayKind kind, const Surface& from, Rgb weight) const;

  // The camera ray's radiance: the root of the recursion.
  Rgb traceCamera(const Ray& ray) const;

 private:
  Rgb shadowTransmittance(const Ray& shadow, const Surface& s) const;
  Rgb lightTerm(const Surface& s, Vec3 l, float distance, Rgb intensity, bool castShadow) const;
  int addNode(RayKind kind, const Ray& ray, const PathState& parentPath, int parentNode, Rgb throughput) const;
  uint32_t materialIndex(const Material* m) const { return static_cast<uint32_t>(m - scene_.materials.data()); }

  const Scene& scene_;
  const Tracer& tracer_;
  WhittedSettings settings_;
  Rng& rng_;
  RayTree* tree_;
  bool transmissive_;  // shadow rays pass through transmissive surfaces only if some material transmits
};

}  // namespace ll::a3
