// Spectra: tabulated functions of wavelength (nm), the CSV tables they come
// from (data/spectra, sources in its README.md), the CIE 1931 colour matching
// functions, and their projection to the linear sRGB an RGB renderer uses.
#pragma once

#include <string>
#include <vector>

#include "core/math.h"

namespace ll {

// Piecewise linear in wavelength. nm strictly increasing, same size as value,
// at least one sample (what loadSpectraCsv guarantees).
struct Spectrum {
  std::vector<float> nm;     // wavelengths, nanometres in vacuum
  std::vector<float> value;  // unit depends on the table (reflectance, n, k, radiance)

  // Linear interpolation; outside [nm.front(), nm.back()] the end value.
  float at(float lambdaNm) const;
};

// The columns of one CSV table: names[i] from the header, columns[i] its data.
struct SpectrumTable {
  std::vector<std::string> names;
  std::vector<Spectrum> columns;
  int headerLine = 0;  // 1-based line of the header in the file, for messages
};

// Reads a table whose header is `wavelength_nm,name1,name2,...` and whose rows
// are numbers: wavelength in nm (> 0, strictly increasing), then one value per
// named column. Blank lines and lines starting with '#' are skipped. Throws
// UserError "file:line:col: ..." for a missing file, a non-number, a
// wavelength that does not increase, a wrong column count or no data rows.
SpectrumTable loadSpectraCsv(const std::string& path);

// CIE 1931 2-degree colour matching functions x̄, ȳ, z̄ at lambdaNm, by the
// multi-lobe piecewise Gaussian fit of C. Wyman, P.-P. Sloan and P. Shirley,
// "Simple Analytic Approximations to the CIE XYZ Color Matching Functions",
// Journal of Computer Graphics Techniques 2(2), 1-11, 2013. Unitless per nm;
// ȳ integrates to about 106.86 over 360-830 nm, as the CIE table does.
float cieX(float lambdaNm);
float cieY(float lambdaNm);
float cieZ(float lambdaNm);

// The range and step reflectanceToRgb integrates over, in nm.
inline constexpr float kCieMinNm = 360.0f;
inline constexpr float kCieMaxNm = 830.0f;

// CIE XYZ to linear sRGB with the IEC 61966-2-1 matrix (D65 white point).
// The result may leave [0,1] for colours outside the sRGB gamut.
Rgb xyzToLinearSrgb(const Vec3& xyz);

// Linear sRGB of a reflectance-like spectrum (unitless, per wavelength) under
// an equal-energy illuminant: XYZ = ∫ s(λ) (x̄,ȳ,z̄)(λ) dλ over 360-830 nm in
// 1 nm steps, to sRGB, divided per channel by the sRGB of the constant 1, so
// that s = 1 gives exactly (1,1,1). Applied to the n and k spectra of a metal
// this gives the per-channel n and k of an RGB renderer: an approximation (the
// Fresnel equations are not linear in n and k), as in Mitsuba's RGB modes.
Rgb reflectanceToRgb(const Spectrum& s);

// XYZ = integral over 360-830 nm of s(lambda) (x, y, z)(lambda) dlambda (nm) to the white-balanced linear
// sRGB reflectanceToRgb gives: divided per channel by the sRGB of the constant spectrum 1. What a spectral
// renderer's XYZ estimate becomes, so its colours and the projected RGB inputs agree.
Rgb xyzToBalancedRgb(const Vec3& xyz);

// Normal-incidence reflectance of a conductor in vacuum,
// R(λ) = ((n-1)² + k²) / ((n+1)² + k²) with n, k interpolated at each 1 nm
// step of reflectanceToRgb, then projected by it: the "Fresnel colour" F0 of
// a metal, computed spectrally and only then reduced to RGB.
Rgb metalNormalReflectance(const Spectrum& n, const Spectrum& k);

// RGB-to-spectrum upsampling by B. Smits, "An RGB-to-Spectrum Conversion for
// Reflectances", Journal of Graphics Tools 4(4), 1999: a linear sRGB
// colour becomes a smooth spectrum, so a spectral renderer can use materials
// and lights given in RGB. The spectrum is min(r,g,b) times a white spectrum,
// plus the gap between the two smaller components times cyan, magenta or
// yellow (the two larger components' secondary), plus the gap between the two
// larger ones times red, green or blue (the largest's primary); the seven basis
// spectra are pbrt-v3's reflectance tables (data/spectra/smits_rgb_to_spectrum.csv,
// see its README.md), as pbrt-v3's SampledSpectrum::FromRGB combines them for
// SpectrumType::Reflectance, but WITHOUT pbrt's 0.94 scale factor.
//
// What comes back: the tables' white is flat at 1.059-1.063, so projecting
// eval by reflectanceToRgb (P) gives P(eval(rgb)) ≈ 1.062 rgb: for a grey
// 1.0618-1.0627 rgb per channel, for the saturated colours of
// spectrum_test.cpp (RgbToSpectrumRoundTrip) 1.062 rgb within 0.021. Scale
// eval by 1 / 1.062 (pbrt uses 0.94) where the reflectance's RGB must be kept.
// Emission: the construction is linear, eval(k rgb) = k eval(rgb) for k >= 0,
// so radiances above 1 work as they are.
class RgbToSpectrum {
 public:
  // Reads a table with columns wavelength_nm and white, cyan, magenta, yellow,
  // red, green, blue (other columns are ignored). Throws UserError
  // "file:line: ..." for what loadSpectraCsv rejects and for missing columns,
  // naming them.
  explicit RgbToSpectrum(const std::string& path);

  // The spectrum of rgb at lambdaNm (nm): negative components are taken as 0,
  // the tables are linear in wavelength between rows and keep their end
  // values outside them (380-720 nm), and the result is clamped to >= 0 (the
  // tables dip to -0.0125 in places). Unitless for a reflectance, the unit of
  // rgb for a radiance.
  float eval(const Rgb& rgb, float lambdaNm) const;

  const std::string& path() const { return path_; }

 private:
  enum Basis { kWhite, kCyan, kMagenta, kYellow, kRed, kGreen, kBlue, kBasisCount };
  std::string path_;
  std::vector<float> nm_;                  // shared by all columns
  std::vector<float> value_[kBasisCount];  // indexed by Basis
};

// The table <spectraDir>/smits_rgb_to_spectrum.csv, read on the first call
// (thread-safe) and kept. Callers pass ll::spectraDirectory()
// (scene/named_metals.h); core/ does not depend on scene/. Every call must
// pass the same directory (asserted). Throws UserError as RgbToSpectrum does;
// a failed first call is retried by the next.
const RgbToSpectrum& defaultRgbToSpectrum(const std::string& spectraDir);

}  // namespace ll
