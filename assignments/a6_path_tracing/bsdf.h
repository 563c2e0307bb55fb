// The BSDF the path tracer samples at a surface point: the scene model's
// material as a sum of lobes. Framework code.
//   diffuse   kd / pi                                   (smooth)
//   glossy    ks (p + 8) / (8 pi) max(0, n.h)^p         (smooth; the Blinn-Phong lobe, energy-normalised)
//   mirror    reflectance `mirror`, the mirror direction (delta)
//   dielectric `transmission` x (Fresnel F reflected, 1 - F refracted) (delta)
// Units: lecture units throughout (a point light of intensity I gives a
// diffuse surface kd I cos / r^2, as in ray casting), which makes the
// diffuse term physical, f = kd / pi, for area lights. Radiance is not
// scaled by (n1/n2)^2 across a refracting surface: for closed objects the
// factors cancel, and Whitted does the same.
#pragma once

#include <optional>

#include "core/math.h"
#include "scene/material.h"

namespace ll::a6 {

// Where a path meets a surface, as the BSDF and next-event estimation see it.
struct ShadingPoint {
  Vec3 position{0.0f};  // world space
  Vec3 ng{0.0f};        // unit geometric normal, turned to wo's side
  Vec3 n{0.0f};         // unit shading normal, turned to wo's side
  Vec3 wo{0.0f};        // unit direction back along the path (towards the previous vertex)
};

// One direction chosen by Bsdf::sample().
struct BsdfSample {
  Vec3 wi{0.0f};       // unit, world space, away from the surface
  Rgb weight{0.0f};    // f |n.wi| / pdf: what the path's throughput is multiplied by
  float pdf = 0.0f;    // density over solid angle of the smooth lobes together (0 for delta lobes)
  bool delta = false;  // mirror or dielectric: a single direction, no next-event estimation
  bool transmitted = false;  // went through the surface (refraction)
};

class Bsdf {
 public:
  // kd: the material's diffuse reflectance at this point (texture applied);
  // n1, n2: refractive indices on wo's side and behind the surface.
  Bsdf(const Material& material, const Rgb& kd, const ShadingPoint& x, float n1, float n2);

  // f(wo, wi) of the smooth lobes, per steradian (0 for wi below the surface).
  Rgb eval(const Vec3& wo, const Vec3& wi) const;
  // Density over solid angle with which sample() picks wi through a smooth lobe.
  float pdf(const Vec3& wo, const Vec3& wi) const;
  // Whether any lobe is smooth (next-event estimation is worth a shadow ray).
  bool hasSmoothLobes() const { return pDiffuse_ + pGlossy_ > 0.0f; }
  // Chooses a lobe with uLobe and a direction in it with u (both uniform in
  // [0,1)); nullopt when the surface reflects nothing or the direction falls
  // below the surface.
  std::optional<BsdfSample> sample(const Vec3& wo, Vec2 u, float uLobe) const;

 private:
  float glossyPdf(const Vec3& wo, const Vec3& wi) const;

  Rgb kd_, ks_, mirror_, transmission_;
  float shininess_;
  float n1_, n2_;
  Vec3 ng_, n_;
  Frame frame_;  // around n_
  // Lobe choice probabilities (by luminance of the lobe's reflectance); they sum to 1 or all are 0.
  float pDiffuse_ = 0.0f, pGlossy_ = 0.0f, pMirror_ = 0.0f, pDielectric_ = 0.0f;
};

}  // namespace ll::a6
