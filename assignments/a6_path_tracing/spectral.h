// Spectral path tracing (`path --set spectral=true`): hero-wavelength
// sampling (Wilkie, Nawaz, Droske, Weidlich and Hanika 2014, "Hero
// Wavelength Spectral Sampling", EGSR). Each path carries three
// wavelengths: a hero drawn uniformly over 360-830 nm and two more spaced a
// third of the range after it (wrapping around), so every path estimates
// the spectrum at three points with one set of directions. The three
// per-wavelength values ride in the channels of an Rgb, so the BSDFs,
// next-event estimation and Beer-Lambert work unchanged; a dispersive
// dielectric (Cauchy index) bends each wavelength its own way, so there the
// path keeps only its hero (channel 0, weighted by 3, as Wilkie et al. do).
//
// Colours: measured spectra where the scene has them (Cornell box, metals);
// RGB inputs upsampled by Smits 1999 (core/spectrum.h). The pixel's CIE XYZ
// is the average of L(lambda) (x, y, z)(lambda) / p(lambda) over the three,
// mapped to linear sRGB with the same white balance as RGB inputs (the
// constant spectrum 1 is (1, 1, 1)), so RGB and spectral renders of a grey
// world agree and differ only where spectra matter.
#pragma once

#include <array>

#include "core/math.h"
#include "core/spectrum.h"
#include "scene/environment.h"
#include "scene/material.h"

namespace ll::a6 {

inline constexpr float kMinNm = 360.0f, kMaxNm = 830.0f;

struct Wavelengths {
  std::array<float, 3> nm{};  // [0] the hero
  static Wavelengths sample(float u);  // u uniform in [0, 1)
};

class SpectralContext {
 public:
  SpectralContext();
  // A linear-sRGB colour as its upsampled spectrum at the three wavelengths.
  Rgb upsample(const Rgb& rgb, const Wavelengths& w) const;
  // A measured spectrum where there is one, else the upsampled colour.
  Rgb at(const Spectrum* measured, const Rgb& rgb, const Wavelengths& w) const;
  // The material as the BSDF sees it at the three wavelengths (texture applied to kd at uv).
  Material materialAt(const Material& m, Vec2 uv, const Wavelengths& w) const;
  // The estimate L(lambda_i), i = 0..2, as linear sRGB (uniform wavelength density).
  Rgb toRgb(const Rgb& radiance, const Wavelengths& w) const;

 private:
  const RgbToSpectrum& upsampler_;
  float gain_ = 1.0f;  // what the upsampler's white projects to (about 1.06), divided out
};

}  // namespace ll::a6
