#include "scene/conductor_fresnel.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace ll {

float fresnelConductor(float cosI, float eta, float k) {
  using C = std::complex<float>;
  cosI = std::clamp(cosI, 0.0f, 1.0f);
  const C n(eta, k);
  const float sin2I = 1.0f - cosI * cosI;
  const C sin2T = sin2I / (n * n);           // Snell's law with a complex index
  const C cosT = std::sqrt(C(1.0f) - sin2T);  // principal root: the transmitted wave decays
  const C rParallel = (n * cosI - cosT) / (n * cosI + cosT);
  const C rPerpendicular = (cosI - n * cosT) / (cosI + n * cosT);
  const float r = 0.5f * (std::norm(rParallel) + std::norm(rPerpendicular));
  return std::isfinite(r) ? std::clamp(r, 0.0f, 1.0f) : 1.0f;
}

Rgb fresnelConductor(float cosI, const Rgb& eta, const Rgb& k) {
  return {fresnelConductor(cosI, eta.r, k.r), fresnelConductor(cosI, eta.g, k.g), fresnelConductor(cosI, eta.b, k.b)};
}

Rgb conductorNormalReflectance(const Rgb& eta, const Rgb& k) {
  const Rgb k2 = k * k;
  return ((eta - 1.0f) * (eta - 1.0f) + k2) / ((eta + 1.0f) * (eta + 1.0f) + k2);
}

}  // namespace ll
