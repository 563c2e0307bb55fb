#include "spectral.h"

#include <cmath>

#include "scene/named_metals.h"

namespace ll::a6 {

Wavelengths Wavelengths::sample(float u) {
  Wavelengths w;
  const float range = kMaxNm - kMinNm;
  for (size_t i = 0; i < 3; ++i) {
    float t = u + static_cast<float>(i) / 3.0f;
    t -= std::floor(t);
    w.nm[i] = kMinNm + range * t;
  }
  return w;
}

SpectralContext::SpectralContext() : upsampler_(defaultRgbToSpectrum(spectraDirectory())) {
  // Smits' white is flat at about 1.06 (core/spectrum.h): divide it out, so an upsampled grey projects back
  // to itself and RGB and spectral renders of a grey world agree.
  Spectrum white;
  for (float nm = kMinNm; nm <= kMaxNm; nm += 1.0f) {
    white.nm.push_back(nm);
    white.value.push_back(upsampler_.eval(Rgb(1.0f), nm));
  }
  const Rgb back = reflectanceToRgb(white);
  gain_ = (back.r + back.g + back.b) / 3.0f;
}

Rgb SpectralContext::upsample(const Rgb& rgb, const Wavelengths& w) const {
  return Rgb(upsampler_.eval(rgb, w.nm[0]), upsampler_.eval(rgb, w.nm[1]), upsampler_.eval(rgb, w.nm[2])) / gain_;
}

Rgb SpectralContext::at(const Spectrum* measured, const Rgb& rgb, const Wavelengths& w) const {
  if (measured == nullptr) return upsample(rgb, w);
  return {measured->at(w.nm[0]), measured->at(w.nm[1]), measured->at(w.nm[2])};
}

Material SpectralContext::materialAt(const Material& m, Vec2 uv, const Wavelengths& w) const {
  Material s;
  s.model = m.model;
  s.roughness = m.roughness;
  s.shininess = m.shininess;
  s.ior = m.iorAt(w.nm[0]);
  s.cauchyB = 0.0f;
  s.ka = upsample(m.ka, w);
  s.kd = m.kdSpectrum && m.texture.kind == Texture::Kind::None ? at(m.kdSpectrum.get(), m.kd, w)
                                                               : upsample(m.diffuse(uv), w);
  s.ks = upsample(m.ks, w);
  s.mirror = upsample(m.mirror, w);
  s.transmission = upsample(m.transmission, w);
  s.absorption = upsample(m.absorption, w);
  s.emission = at(m.emissionSpectrum.get(), m.emission, w);
  s.eta = m.etaSpectrum ? at(m.etaSpectrum.get(), m.eta, w) : upsample(m.eta, w);
  s.k = m.kSpectrum ? at(m.kSpectrum.get(), m.k, w) : upsample(m.k, w);
  return s;
}

Rgb SpectralContext::toRgb(const Rgb& radiance, const Wavelengths& w) const {
  Vec3 xyz(0.0f);
  for (size_t i = 0; i < 3; ++i) {
    const float l = radiance[static_cast<int>(i)];
    xyz += l * Vec3(cieX(w.nm[i]), cieY(w.nm[i]), cieZ(w.nm[i]));
  }
  // Monte Carlo over wavelength: the mean of f(lambda) / p(lambda) with p = 1 / (range), an integral in nm.
  xyz *= (kMaxNm - kMinNm) / 3.0f;
  return xyzToBalancedRgb(xyz);
}

}  // namespace ll::a6
