// Next-event estimation's side of the path tracer: choosing a light and a
// point on it, the density of that choice, visibility and the MIS weight.
// Framework code.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "bsdf.h"
#include "core/math.h"
#include "render/tracer.h"
#include "scene/scene.h"

namespace ll::a6 {

// One light sample, as next-event estimation (A6.2) receives it.
struct LightSample {
  enum class Kind { Area, Point, Directional };
  Kind kind = Kind::Area;
  Vec3 position{0.0f};   // Area: the point y on the light; Point: the light's position (world space)
  Vec3 normal{0.0f};     // Area: unit normal of y's emitting side
  Vec3 direction{0.0f};  // Directional: unit, the way the light travels
  Rgb emission{0.0f};    // Area: radiance Le; Point, Directional: intensity I (lecture units)
  float pdf = 0.0f;      // Area: density of y per unit area, the light's choice included; else: choice probability
  bool castShadow = true;  // false: nothing can stand between this light and a surface (no shadow ray needed)
  const Material* material = nullptr;  // Area: the emitter's material (for its spectrum); else nullptr
  bool sky = false;      // the sample is on the sky (an Area sample at kSkyDistance)
};

// Lights chosen uniformly (each point, directional and area light, and the
// sky when it is not black, with probability 1 / count), area lights
// sampled uniformly by area. The sky (scene/environment.h) is the lecture's
// big sphere around the scene: a direction w from its own distribution
// becomes an area sample on a sphere of radius kSkyDistance around the
// shading point, y = x + kSkyDistance w with normal -w, whose density per
// area is pdf(w) / kSkyDistance^2 -- so A6.2's area-light code computes the
// sky's term unchanged (the solid-angle density it converts back is pdf(w)).
class LightSampler {
 public:
  explicit LightSampler(const Scene& scene);
  bool empty() const { return count_ == 0; }
  // uChoice, u uniform in [0,1); from: the shading point (the sky's sample is placed around it).
  // Precondition: !empty().
  LightSample sample(float uChoice, Vec2 u, const Vec3& from) const;
  // Density over solid angle with which sample() produces the point of
  // emissive primitive `prim` seen at `distance` under cos(theta_y) =
  // cosLight (> 0) from the shading point; 0 if prim belongs to no area light.
  float pdfSolidAngle(uint32_t prim, float distance, float cosLight) const;
  // Density over solid angle with which sample() produces the sky in unit direction dir; 0 without a sky light.
  float pdfSky(const Vec3& dir) const;
  bool hasSky() const { return sky_; }

  // How far the sky's sample points are placed: beyond any scene (coordinates stay within 1e8,
  // scene/scene_limits.h), while kSkyDistance^2 stays far from float overflow.
  static constexpr float kSkyDistance = 1e10f;
 private:
  const Scene& scene_;
  std::vector<int> areaLightOfObject_;  // object index -> area light index, or -1
  size_t count_ = 0;
  bool sky_ = false;  // the last choice is the sky
};

// Whether nothing blocks the segment from x (leaving on wi's side) along
// unit direction wi for `distance` (+infinity: to infinity), counted as a
// shadow ray. The segment ends just before the light so its own surface never blocks it.
bool visible(const Tracer& tracer, const ShadingPoint& x, const Vec3& wi, float distance);

// Veach's power heuristic (beta = 2): the weight of a sample drawn with
// density pdfA when pdfB is the other strategy's density for the same direction.
inline float powerHeuristic(float pdfA, float pdfB) {
  const float a = pdfA * pdfA, b = pdfB * pdfB;
  if (std::isinf(a)) return std::isinf(b) ? 0.5f : 1.0f;  // squares of huge densities overflow
  return a + b > 0.0f ? a / (a + b) : 0.0f;
}

}  // namespace ll::a6
