// Fresnel reflectance of a conductor (a metal): the complex refractive index
// n + ik, relative to the medium the light comes from. Exact unpolarised
// form (Born and Wolf; pbrt-v4's FrComplex written per channel). The
// rasterizer, ray casting and Whitted show a metal by its colour at normal
// incidence, F0 = ((n-1)^2 + k^2) / ((n+1)^2 + k^2); the path tracer
// evaluates the whole curve, which whitens towards grazing angles.
#pragma once

#include "core/math.h"

namespace ll {

// cosI: cosine between the incident direction and the (micro)normal, in [0,1].
// Returns the reflected fraction per channel, in [0,1].
float fresnelConductor(float cosI, float eta, float k);
Rgb fresnelConductor(float cosI, const Rgb& eta, const Rgb& k);

// F0, the reflectance at normal incidence.
Rgb conductorNormalReflectance(const Rgb& eta, const Rgb& k);

}  // namespace ll
