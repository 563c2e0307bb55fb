#include "bsdf.h"

#include <algorithm>
#include <cmath>

#include "a3_tasks.h"
#include "a6_tasks.h"
#include "scene/conductor_fresnel.h"

namespace ll::a6 {

namespace {

Vec3 reflectAbout(const Vec3& wo, const Vec3& n) { return 2.0f * glm::dot(wo, n) * n - wo; }

// The dielectric Fresnel reflectance at cosI (> 0) from n1 into n2; 1 under total internal reflection.
float dielectricReflectance(float cosI, float n1, float n2) {
  const float eta = n1 / n2, sin2T = eta * eta * (1.0f - cosI * cosI);
  if (sin2T >= 1.0f) return 1.0f;
  return std::clamp(a3::fresnelDielectric(std::clamp(cosI, 0.0f, 1.0f), n1, n2).unpolarized(), 0.0f, 1.0f);
}

// The Blinn-Phong lobe's normalisation C in f = ks C max(0, n.h)^p: its directional albedo is largest seen
// from straight above (wo = n), where integral C cos^p(theta_h) cos(theta_i) d omega_i = 1 gives
// C = 1 / (8 pi [2 (1 - 2^-(p+4)/2) / (p + 4) - (1 - 2^-(p+2)/2) / (p + 2)]) (theta_i = 2 theta_h);
// 1 / pi at p = 0. Real-time graphics' (p + 8) / (8 pi) is up to 6 % larger there (p = 20) and makes
// light: measured in tests/numerics/bsdf_test.cpp.
float blinnPhongNormalisation(float p) {
  const double q = static_cast<double>(p);
  const double integral = 2.0 * (1.0 - std::pow(2.0, -(q + 4.0) / 2.0)) / (q + 4.0) -
                          (1.0 - std::pow(2.0, -(q + 2.0) / 2.0)) / (q + 2.0);
  return static_cast<float>(1.0 / (8.0 * kPiD * integral));
}

// Heitz 2014's height-correlated masking-shadowing from the two one-sided G1 = 1 / (1 + Lambda).
float smithG2(float g1o, float g1i) {
  if (!(g1o > 0.0f) || !(g1i > 0.0f)) return 0.0f;
  return 1.0f / (1.0f / g1o + 1.0f / g1i - 1.0f);
}

}  // namespace

Bsdf::Bsdf(const Material& m, const Rgb& kd, const ShadingPoint& x, float n1, float n2)
    : kd_(kd), ks_(m.ks), mirror_(m.mirror), transmission_(m.transmission), shininess_(m.shininess), n1_(n1),
      n2_(n2), ng_(x.ng), n_(x.n), frame_(x.n), model_(m.model), alpha_(m.roughness) {
  const bool rough = alpha_ >= kSmoothRoughness;
  if (model_ == BsdfModel::Conductor) {
    eta_ = m.eta / n1;  // relative to the medium the light comes from
    k_ = m.k / n1;
    smoothConductor_ = !rough;
    (rough ? pMicrofacet_ : pMirror_) = 1.0f;
    return;
  }
  // Between equal indices light passes straight through every facet: the smooth lobe (a delta) says so.
  if (model_ == BsdfModel::RoughDielectric && rough && std::abs(n1 - n2) > 1e-4f * n2) {
    pMicrofacet_ = 1.0f;
    return;
  }
  glossyNorm_ = blinnPhongNormalisation(shininess_);
  const float wd = std::max(0.0f, luminance(kd_)), wg = std::max(0.0f, luminance(ks_));
  const float wm = std::max(0.0f, luminance(mirror_)), wt = std::max(0.0f, luminance(transmission_));
  const float sum = wd + wg + wm + wt;
  if (sum > 0.0f) {
    pDiffuse_ = wd / sum;
    pGlossy_ = wg / sum;
    pMirror_ = wm / sum;
    pDielectric_ = wt / sum;
  }
}

float Bsdf::glossyPdf(const Vec3& wo, const Vec3& wi) const {
  const Vec3 h = glm::normalize(wo + wi);
  const float cosH = glm::dot(n_, h), woH = glm::dot(wo, h);
  if (cosH <= 0.0f || woH <= 0.0f) return 0.0f;
  // h has density (p + 1) / (2 pi) cos^p around n; wi = reflect(wo, h) maps it with Jacobian 1 / (4 wo.h).
  return (shininess_ + 1.0f) / (2.0f * kPi) * std::pow(cosH, shininess_) / (4.0f * woH);
}

Rgb Bsdf::eval(const Vec3& wo, const Vec3& wi) const {
  if (pMicrofacet_ > 0.0f) {
    const bool reflected = glm::dot(ng_, wi) > 0.0f;  // the geometry decides the side (shading normals)
    if (reflected != (glm::dot(n_, wi) > 0.0f)) return Rgb(0.0f);
    return microfacetEval(frame_.toLocal(wo), frame_.toLocal(wi));
  }
  if (glm::dot(ng_, wi) <= 0.0f || glm::dot(n_, wi) <= 0.0f) return Rgb(0.0f);  // smooth lobes only reflect
  Rgb f = kd_ / kPi;
  if (pGlossy_ > 0.0f) {
    const float cosH = glm::dot(n_, glm::normalize(wo + wi));
    if (cosH > 0.0f) f += ks_ * (glossyNorm_ * std::pow(cosH, shininess_));
  }
  return f;
}

float Bsdf::pdf(const Vec3& wo, const Vec3& wi) const {
  if (pMicrofacet_ > 0.0f) {
    const bool reflected = glm::dot(ng_, wi) > 0.0f;
    if (reflected != (glm::dot(n_, wi) > 0.0f)) return 0.0f;
    return microfacetPdf(frame_.toLocal(wo), frame_.toLocal(wi));
  }
  if (glm::dot(ng_, wi) <= 0.0f) return 0.0f;
  const float cosI = glm::dot(n_, wi);
  float p = 0.0f;
  if (pDiffuse_ > 0.0f) p += pDiffuse_ * cosineHemispherePdf(cosI);
  if (pGlossy_ > 0.0f) p += pGlossy_ * glossyPdf(wo, wi);
  return p;
}

std::optional<BsdfSample> Bsdf::sample(const Vec3& wo, Vec2 u, float uLobe) const {
  if (pMicrofacet_ > 0.0f) {
    std::optional<BsdfSample> s = microfacetSample(frame_.toLocal(wo), u, uLobe);
    if (!s) return s;
    s->wi = glm::normalize(frame_.toWorld(s->wi));
    if ((glm::dot(ng_, s->wi) > 0.0f) == s->transmitted) return std::nullopt;  // shading normals: wrong side
    return s;
  }
  BsdfSample s;
  if (uLobe < pDiffuse_ + pGlossy_) {  // a smooth lobe: the direction, then the mixture's density
    if (uLobe < pDiffuse_) {
      s.wi = frame_.toWorld(sampleCosineHemisphere(u));
    } else {
      const float cosH = std::pow(1.0f - u.x, 1.0f / (shininess_ + 1.0f));  // density (p+1)/(2 pi) cos^p
      const float sinH = std::sqrt(std::max(0.0f, 1.0f - cosH * cosH)), phi = 2.0f * kPi * u.y;
      const Vec3 h = frame_.toWorld(Vec3(sinH * std::cos(phi), sinH * std::sin(phi), cosH));
      s.wi = reflectAbout(wo, h);
    }
    const float cosI = glm::dot(n_, s.wi);
    if (glm::dot(ng_, s.wi) <= 0.0f || cosI <= 0.0f) return std::nullopt;  // below the surface
    s.wi = glm::normalize(s.wi);
    s.pdf = pdf(wo, s.wi);
    if (!(s.pdf > 0.0f)) return std::nullopt;
    s.weight = eval(wo, s.wi) * (cosI / s.pdf);
    return s;
  }
  s.delta = true;
  if (uLobe < pDiffuse_ + pGlossy_ + pMirror_) {
    s.wi = reflectAbout(wo, n_);
    s.weight = smoothConductor_ ? fresnelConductor(glm::dot(wo, n_), eta_, k_) : mirror_ / pMirror_;
  } else if (pDielectric_ > 0.0f) {
    // Fresnel decides between reflection and refraction (A3.3's equations).
    const float cosI = std::clamp(glm::dot(wo, n_), 0.0f, 1.0f), eta = n1_ / n2_;
    const float sin2T = eta * eta * (1.0f - cosI * cosI);
    const float f = sin2T >= 1.0f ? 1.0f : dielectricReflectance(cosI, n1_, n2_);
    if (u.x < f) {
      s.wi = reflectAbout(wo, n_);
    } else {
      const float cosT = std::sqrt(1.0f - sin2T);
      s.wi = glm::normalize(-eta * wo + (eta * cosI - cosT) * n_);
      s.transmitted = true;
    }
    s.weight = transmission_ / pDielectric_;  // F (or 1 - F) cancels with its own choice probability
  } else {
    return std::nullopt;  // black: nothing is reflected
  }
  // A delta direction on the wrong side of the geometry (shading normals) ends the path.
  if ((glm::dot(ng_, s.wi) > 0.0f) == s.transmitted) return std::nullopt;
  return s;
}

// --- The microfacet lobes, in the local frame (z = n, wo.z > 0). ---

Rgb Bsdf::microfacetEval(const Vec3& wo, const Vec3& wi) const {
  const float cosO = wo.z, cosI = wi.z;
  if (!(cosO > 0.0f) || cosI == 0.0f) return Rgb(0.0f);
  if (model_ == BsdfModel::Conductor) {
    if (cosI < 0.0f) return Rgb(0.0f);
    const Vec3 h = glm::normalize(wo + wi);
    const float g2 = smithG2(smithMasking(wo, alpha_), smithMasking(wi, alpha_));
    return fresnelConductor(glm::dot(wo, h), eta_, k_) *
           (ggxDistribution(h, alpha_) * g2 / (4.0f * cosO * cosI));
  }
  // Rough glass: the side of wi says reflection or refraction.
  const Vec3 flip(1.0f, 1.0f, -1.0f);  // G1 of a direction below the surface, seen from its own side
  if (cosI > 0.0f) {
    const Vec3 h = glm::normalize(wo + wi);
    const float f = dielectricReflectance(glm::dot(wo, h), n1_, n2_);
    const float g2 = smithG2(smithMasking(wo, alpha_), smithMasking(wi, alpha_));
    return transmission_ * (f * ggxDistribution(h, alpha_) * g2 / (4.0f * cosO * cosI));
  }
  Vec3 h = n1_ * wo + n2_ * wi;  // Walter's generalised half vector, towards wo's side
  if (glm::dot(h, h) <= 0.0f) return Rgb(0.0f);
  h = glm::normalize(h);
  if (h.z < 0.0f) h = -h;
  const float oh = glm::dot(wo, h), ih = glm::dot(wi, h);
  if (oh <= 0.0f || ih >= 0.0f) return Rgb(0.0f);  // not a refraction through h
  const float t = 1.0f - dielectricReflectance(oh, n1_, n2_);
  const float g2 = smithG2(smithMasking(wo, alpha_), smithMasking(wi * flip, alpha_));
  const float denom = n1_ * oh + n2_ * ih;  // (n1 wo.h + n2 wi.h)^2 / n2^2 is pbrt's (wi.h + wo.h / eta)^2
  return transmission_ * (t * ggxDistribution(h, alpha_) * g2 * oh * -ih * n2_ * n2_ /
                          (cosO * -cosI * denom * denom));
}

float Bsdf::microfacetPdf(const Vec3& wo, const Vec3& wi) const {
  if (!(wo.z > 0.0f) || wi.z == 0.0f) return 0.0f;
  const float g1o = smithMasking(wo, alpha_);
  if (model_ == BsdfModel::Conductor || wi.z > 0.0f) {
    if (wi.z < 0.0f) return 0.0f;
    const Vec3 h = glm::normalize(wo + wi);
    const float oh = glm::dot(wo, h);
    if (oh <= 0.0f) return 0.0f;
    // visible normal density D_wo(h) = G1 (wo.h) D / wo.z, times the reflection Jacobian 1 / (4 wo.h)
    const float visible = g1o * ggxDistribution(h, alpha_) / (4.0f * wo.z);
    return model_ == BsdfModel::Conductor ? visible : visible * dielectricReflectance(oh, n1_, n2_);
  }
  Vec3 h = n1_ * wo + n2_ * wi;
  if (glm::dot(h, h) <= 0.0f) return 0.0f;
  h = glm::normalize(h);
  if (h.z < 0.0f) h = -h;
  const float oh = glm::dot(wo, h), ih = glm::dot(wi, h);
  if (oh <= 0.0f || ih >= 0.0f) return 0.0f;
  const float denom = n1_ * oh + n2_ * ih;
  // D_wo(h) times the refraction Jacobian n2^2 |wi.h| / (n1 wo.h + n2 wi.h)^2, times the chance to refract
  return g1o * oh * ggxDistribution(h, alpha_) / wo.z * (n2_ * n2_ * -ih / (denom * denom)) *
         (1.0f - dielectricReflectance(oh, n1_, n2_));
}

std::optional<BsdfSample> Bsdf::microfacetSample(const Vec3& wo, Vec2 u, float uLobe) const {
  if (!(wo.z > 0.0f)) return std::nullopt;
  const Vec3 h = sampleGgxVisibleNormal(wo, alpha_, u);
  const float oh = glm::dot(wo, h);
  if (!(oh > 0.0f)) return std::nullopt;
  BsdfSample s;
  bool refract = false;
  if (model_ == BsdfModel::RoughDielectric) refract = uLobe >= dielectricReflectance(oh, n1_, n2_);
  if (!refract) {
    s.wi = reflectAbout(wo, h);
    if (s.wi.z <= 0.0f) return std::nullopt;  // reflected below the surface: the light is masked
  } else {
    const float eta = n1_ / n2_, sin2T = eta * eta * (1.0f - oh * oh);
    if (sin2T >= 1.0f) return std::nullopt;  // cannot happen: F = 1 there
    s.wi = glm::normalize(-eta * wo + (eta * oh - std::sqrt(1.0f - sin2T)) * h);
    if (s.wi.z >= 0.0f) return std::nullopt;
    s.transmitted = true;
  }
  s.pdf = microfacetPdf(wo, s.wi);
  if (!(s.pdf > 0.0f)) return std::nullopt;
  const Rgb f = microfacetEval(wo, s.wi);
  s.weight = f * (std::abs(s.wi.z) / s.pdf);
  if (!isFinite(s.weight)) return std::nullopt;
  return s;
}

}  // namespace ll::a6
