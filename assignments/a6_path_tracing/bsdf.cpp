#include "bsdf.h"

#include <algorithm>
#include <cmath>

#include "a3_tasks.h"
#include "a6_tasks.h"

namespace ll::a6 {

namespace {

Vec3 reflectAbout(const Vec3& wo, const Vec3& n) { return 2.0f * glm::dot(wo, n) * n - wo; }

}  // namespace

Bsdf::Bsdf(const Material& m, const Rgb& kd, const ShadingPoint& x, float n1, float n2)
    : kd_(kd), ks_(m.ks), mirror_(m.mirror), transmission_(m.transmission), shininess_(m.shininess), n1_(n1),
      n2_(n2), ng_(x.ng), n_(x.n), frame_(x.n) {
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
  if (glm::dot(ng_, wi) <= 0.0f || glm::dot(n_, wi) <= 0.0f) return Rgb(0.0f);  // smooth lobes only reflect
  Rgb f = kd_ / kPi;
  if (pGlossy_ > 0.0f) {
    const float cosH = glm::dot(n_, glm::normalize(wo + wi));
    if (cosH > 0.0f) f += ks_ * ((shininess_ + 8.0f) / (8.0f * kPi) * std::pow(cosH, shininess_));
  }
  return f;
}

float Bsdf::pdf(const Vec3& wo, const Vec3& wi) const {
  if (glm::dot(ng_, wi) <= 0.0f) return 0.0f;
  const float cosI = glm::dot(n_, wi);
  float p = 0.0f;
  if (pDiffuse_ > 0.0f) p += pDiffuse_ * cosineHemispherePdf(cosI);
  if (pGlossy_ > 0.0f) p += pGlossy_ * glossyPdf(wo, wi);
  return p;
}

std::optional<BsdfSample> Bsdf::sample(const Vec3& wo, Vec2 u, float uLobe) const {
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
    s.weight = mirror_ / pMirror_;
  } else if (pDielectric_ > 0.0f) {
    // Fresnel decides between reflection and refraction (A3.3's equations).
    const float cosI = std::clamp(glm::dot(wo, n_), 0.0f, 1.0f), eta = n1_ / n2_;
    const float sin2T = eta * eta * (1.0f - cosI * cosI);
    const float f = sin2T >= 1.0f ? 1.0f : std::clamp(a3::fresnelDielectric(cosI, n1_, n2_).unpolarized(), 0.0f, 1.0f);
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

}  // namespace ll::a6
