// The metals a conductor material may name ("metal": "copper"), read from
// the measured complex refractive indices in data/spectra (sources and
// licences in data/spectra/README.md), and their per-channel n and k for an
// RGB renderer: each spectrum projected to linear sRGB (core/spectrum.h).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"
#include "core/spectrum.h"

namespace ll {

struct MetalIndex {
  Rgb eta{1.0f};     // real part n, relative to vacuum
  Rgb k{0.0f};       // extinction
  std::string file;  // the table it came from
  std::shared_ptr<const Spectrum> etaSpectrum, kSpectrum;  // the measured curves themselves
};

// The names a scene may use: aluminium, copper, gold, silver.
const std::vector<std::string>& metalNames();
// nullopt for an unknown name. Throws UserError if the table is missing or
// malformed (file and line). Tables are read once per process.
std::optional<MetalIndex> namedMetal(const std::string& name);

// Where the spectral tables live: $LIGHTLAB_SPECTRA_DIR, else the checkout's data/spectra.
std::string spectraDirectory();

}  // namespace ll
