// Materials of the scene model: "Material = BRDF". A material names its
// scattering model (`bsdf` in a scene file, data/scenes/README.md): the
// lecture's Blinn-Phong terms plus mirror, dielectric and emission (the
// default, as scenes always had it), lambert, conductor (a GGX microfacet
// metal), dielectric (smooth glass) or rough-dielectric. The path tracer
// evaluates the model itself; the rasterizer (CPU and its GPU twin), ray
// casting and Whitted see
// every model through the Blinn-Phong fields below, which the loader fills
// with the model's local and specular limit (a metal: its Fresnel colour at
// normal incidence as mirror and highlight). All colours are linear RGB in
// [0, inf).
#pragma once

#include <memory>
#include <string>

#include "core/image.h"
#include "core/math.h"
#include "core/spectrum.h"

namespace ll {

// A diffuse texture: an image (bilinear, repeating) or a procedural checker
// over uv in [0,1]^2. Multiplies (image) or replaces (checker) kd.
struct Texture {
  enum class Kind { None, Image, Checker };
  Kind kind = Kind::None;
  std::shared_ptr<const Image> image;
  Vec2 squares{8.0f};  // checker squares along u and v
  Rgb colorA{1.0f}, colorB{0.0f};

  Rgb eval(Vec2 uv) const;
};

enum class BsdfModel { BlinnPhong, Lambert, Conductor, Dielectric, RoughDielectric };

// Below this GGX alpha a microfacet surface is treated as smooth (a delta lobe).
inline constexpr float kSmoothRoughness = 1e-3f;

struct Material {
  std::string name;
  BsdfModel model = BsdfModel::BlinnPhong;
  float roughness = 0.0f;  // GGX (Trowbridge-Reitz) alpha of conductor and rough-dielectric, in [0, 1]
  Rgb eta{1.0f};           // conductor: real part n of the complex index n + ik (per channel)
  Rgb k{0.0f};             // conductor: extinction k
  std::string metal;       // conductor: the named metal eta and k were read from ("" when given)
  // Measured spectra where the scene gives them (data/spectra); the RGB fields above hold their projection
  // to linear sRGB (core/spectrum.h), which RGB rendering uses. `path --set spectral=true` uses the spectra.
  std::shared_ptr<const Spectrum> kdSpectrum;        // diffuse reflectance
  std::shared_ptr<const Spectrum> emissionSpectrum;  // emitted radiance
  std::shared_ptr<const Spectrum> etaSpectrum, kSpectrum;  // conductor: n and k of a named metal
  // Dispersion (Cauchy 1836): n(lambda) = ior + cauchyB * (1 / lambda^2 - 1 / 0.5876^2), lambda in
  // micrometres, so `ior` is the index at the helium d-line (587.6 nm) that RGB rendering uses. 0 = none.
  float cauchyB = 0.0f;
  bool dispersive() const { return cauchyB != 0.0f; }
  // The index of refraction at wavelength lambdaNm.
  float iorAt(float lambdaNm) const {
    if (cauchyB == 0.0f) return ior;
    const float um = lambdaNm * 1e-3f;
    return ior + cauchyB * (1.0f / (um * um) - 1.0f / (0.5876f * 0.5876f));
  }
  Rgb ka{0.0f};            // ambient reflectance
  Rgb kd{0.0f};            // diffuse reflectance (albedo)
  Rgb ks{0.0f};            // specular reflectance of the Blinn-Phong highlight
  float shininess = 1.0f;  // Blinn-Phong exponent p
  Rgb mirror{0.0f};        // perfect mirror reflectance
  Rgb transmission{0.0f};  // dielectric transmittance
  float ior = 1.0f;        // index of refraction of the inside
  Rgb absorption{0.0f};    // Beer-Lambert coefficient, 1 / scene unit
  Rgb emission{0.0f};      // emitted radiance
  Texture texture;

  Rgb diffuse(Vec2 uv) const;
  bool emits() const { return !isBlack(emission); }
  bool reflectsMirror() const { return !isBlack(mirror); }
  bool transmits() const { return !isBlack(transmission); }
  bool glossy() const { return !isBlack(ks); }
  // A rough microfacet lobe: glossy reflection of the whole scene, which only `path` simulates.
  bool glossyScattering() const {
    return (model == BsdfModel::Conductor || model == BsdfModel::RoughDielectric) && roughness >= kSmoothRoughness;
  }
};

}  // namespace ll
