// The BSDF the path tracer samples at a surface point: the material's
// scattering model (scene/material.h). Framework code.
//
// blinn-phong, lambert and dielectric: a sum of lobes
//   diffuse   kd / pi                                   (smooth)
//   glossy    ks C(p) max(0, n.h)^p                     (smooth; the Blinn-Phong lobe, C(p) ~ (p + 6) / (8 pi)
//                                                       makes its albedo exactly 1 at normal incidence, below
//                                                       elsewhere: it never creates energy)
//   mirror    reflectance `mirror`, the mirror direction (delta)
//   dielectric `transmission` x (Fresnel F reflected, 1 - F refracted) (delta)
// conductor: the GGX microfacet metal (Walter et al. 2007; Heitz 2014 for
// the height-correlated masking-shadowing G2, A6.4 for D, G1 and sampling)
//   f = F(wo.h) D(h) G2(wo, wi) / (4 cos_o cos_i), F the conductor Fresnel
//   of n + ik; sampled by visible normals, so f cos / pdf = F G2 / G1(wo).
//   Below roughness 1e-3 a delta mirror with the same Fresnel.
// rough-dielectric: Walter et al. 2007's rough glass, reflection through
//   h = (wo + wi) / |...| and refraction through h = -(n1 wo + n2 wi) / |...|,
//   chosen by Fresnel at the sampled visible normal. As single-scattering
//   microfacet models both lose energy at high roughness (light that would
//   bounce between facets ends; measured in tests/numerics/bsdf_test.cpp).
// Units: lecture units throughout (a point light of intensity I gives a
// diffuse surface kd I cos / r^2, as in ray casting), which makes the
// diffuse term physical, f = kd / pi, for area lights. Radiance is not
// scaled by (n1/n2)^2 across a refracting surface: for closed objects the
// factors cancel, and Whitted does the same. So the refraction lobes obey
// the reciprocity of the adjoint BSDF, f(wo, wi) / n(wi)^2 = f(wi, wo) / n(wo)^2.
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
  bool transmitted = false;  // went through the surface (refraction; next-event estimation sees no light there)
};

class Bsdf {
 public:
  // kd: the material's diffuse reflectance at this point (texture applied);
  // n1, n2: refractive indices on wo's side and behind the surface.
  Bsdf(const Material& material, const Rgb& kd, const ShadingPoint& x, float n1, float n2);

  // f(wo, wi) of the smooth lobes, per steradian (0 for wi below the surface, except rough glass's refraction).
  Rgb eval(const Vec3& wo, const Vec3& wi) const;
  // Density over solid angle with which sample() picks wi through a smooth lobe.
  float pdf(const Vec3& wo, const Vec3& wi) const;
  // Whether any lobe is smooth (next-event estimation is worth a shadow ray).
  bool hasSmoothLobes() const { return pDiffuse_ + pGlossy_ + pMicrofacet_ > 0.0f; }
  // Chooses a lobe with uLobe and a direction in it with u (both uniform in
  // [0,1)); nullopt when the surface reflects nothing or the direction falls
  // below the surface.
  std::optional<BsdfSample> sample(const Vec3& wo, Vec2 u, float uLobe) const;

 private:
  float glossyPdf(const Vec3& wo, const Vec3& wi) const;
  Rgb microfacetEval(const Vec3& wo, const Vec3& wi) const;  // conductor or rough glass, local directions
  float microfacetPdf(const Vec3& wo, const Vec3& wi) const;
  std::optional<BsdfSample> microfacetSample(const Vec3& wo, Vec2 u, float uLobe) const;

  Rgb kd_, ks_, mirror_, transmission_;
  float shininess_;
  float glossyNorm_ = 0.0f;  // C of the Blinn-Phong lobe (bsdf.cpp): its albedo is at most 1
  float n1_, n2_;
  Vec3 ng_, n_;
  Frame frame_;  // around n_
  BsdfModel model_;
  float alpha_ = 0.0f;          // GGX roughness of the microfacet lobe
  Rgb eta_{1.0f}, k_{0.0f};     // conductor's index relative to wo's medium
  // Lobe choice probabilities (by luminance of the lobe's reflectance); they sum to 1 or all are 0.
  float pDiffuse_ = 0.0f, pGlossy_ = 0.0f, pMirror_ = 0.0f, pDielectric_ = 0.0f;
  float pMicrofacet_ = 0.0f;  // 1 for a rough conductor or rough glass (their only lobe)
  bool smoothConductor_ = false;
};

}  // namespace ll::a6
