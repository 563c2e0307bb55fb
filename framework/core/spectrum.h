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

// Normal-incidence reflectance of a conductor in vacuum,
// R(λ) = ((n-1)² + k²) / ((n+1)² + k²) with n, k interpolated at each 1 nm
// step of reflectanceToRgb, then projected by it: the "Fresnel colour" F0 of
// a metal, computed spectrally and only then reduced to RGB.
Rgb metalNormalReflectance(const Spectrum& n, const Spectrum& k);

}  // namespace ll
