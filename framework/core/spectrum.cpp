#include "core/spectrum.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <charconv>
#include <cmath>
#include <set>
#include <string_view>

#include "core/error.h"
#include "core/files.h"

namespace ll {

float Spectrum::at(float lambdaNm) const {
  assert(!nm.empty() && nm.size() == value.size());
  if (lambdaNm <= nm.front()) return value.front();
  if (lambdaNm >= nm.back()) return value.back();
  const size_t i =
      static_cast<size_t>(std::upper_bound(nm.begin(), nm.end(), lambdaNm) - nm.begin());
  const float t = (lambdaNm - nm[i - 1]) / (nm[i] - nm[i - 1]);
  return value[i - 1] + t * (value[i] - value[i - 1]);
}

namespace {

struct Cell {
  std::string_view text;  // trimmed
  int column;             // 1-based, of the first character of text
};

// One CSV line split at commas, each cell trimmed of spaces and tabs.
std::vector<Cell> splitCells(std::string_view line) {
  std::vector<Cell> cells;
  size_t start = 0;
  while (true) {
    const size_t comma = std::min(line.find(',', start), line.size());
    size_t b = start, e = comma;
    while (b < e && (line[b] == ' ' || line[b] == '\t')) ++b;
    while (e > b && (line[e - 1] == ' ' || line[e - 1] == '\t')) --e;
    cells.push_back({line.substr(b, e - b), static_cast<int>(b) + 1});
    if (comma == line.size()) return cells;
    start = comma + 1;
  }
}

float parseNumber(const Cell& cell, const std::string& path, int line, const std::string& column) {
  float v = 0.0f;
  const char* end = cell.text.data() + cell.text.size();
  const auto [ptr, ec] = std::from_chars(cell.text.data(), end, v);
  if (ec != std::errc() || ptr != end || !std::isfinite(v))
    throwUserError(
        path, line, cell.column,
        "'" + std::string(cell.text) + "' in column " + column + " is not a finite number");
  return v;
}

}  // namespace

SpectrumTable loadSpectraCsv(const std::string& path) {
  const std::string text = readTextFile(path, "spectrum table");
  SpectrumTable table;
  std::string expected;    // "wavelength_nm, n, k" for messages
  std::string lastNmText;  // the previous row's wavelength as written
  int headerLine = 0, lineNo = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) eol = text.size();
    std::string_view line(text.data() + pos, eol - pos);
    pos = eol + 1;
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.find_first_not_of(" \t") == std::string_view::npos || line.front() == '#') continue;
    const std::vector<Cell> cells = splitCells(line);

    if (headerLine == 0) {
      headerLine = lineNo;
      table.headerLine = lineNo;
      if (cells[0].text != "wavelength_nm")
        throwUserError(
            path, lineNo, cells[0].column,
            "the header must start with wavelength_nm, then one name per spectrum (found '" +
                std::string(cells[0].text) + "')");
      if (cells.size() < 2)
        throwUserError(path, lineNo, 0, "the header names no spectrum after wavelength_nm");
      std::set<std::string_view> seen;
      expected = "wavelength_nm";
      for (size_t i = 1; i < cells.size(); ++i) {
        if (cells[i].text.empty())
          throwUserError(path, lineNo, cells[i].column, "empty column name");
        if (!seen.insert(cells[i].text).second)
          throwUserError(path, lineNo, cells[i].column,
                         "column name '" + std::string(cells[i].text) + "' repeated");
        table.names.emplace_back(cells[i].text);
        expected += ", " + table.names.back();
      }
      table.columns.resize(table.names.size());
      continue;
    }

    if (cells.size() != table.names.size() + 1)
      throwUserError(path, lineNo, 0,
                     std::to_string(cells.size()) + " values; the header asks for " +
                         std::to_string(table.names.size() + 1) + " (" + expected + ")");
    const float nm = parseNumber(cells[0], path, lineNo, "wavelength_nm");
    if (nm <= 0.0f) throwUserError(path, lineNo, cells[0].column, "wavelength_nm must be positive");
    const std::vector<float>& previous = table.columns[0].nm;
    if (!previous.empty() && nm <= previous.back())
      throwUserError(path, lineNo, cells[0].column,
                     "wavelength_nm " + std::string(cells[0].text) +
                         " is not above the previous row's " + lastNmText +
                         " (wavelengths must strictly increase)");
    lastNmText = cells[0].text;
    for (size_t i = 0; i < table.names.size(); ++i) {
      table.columns[i].nm.push_back(nm);
      table.columns[i].value.push_back(parseNumber(cells[i + 1], path, lineNo, table.names[i]));
    }
  }
  if (headerLine == 0)
    throwUserError(path, 1, 0, "no header (expected wavelength_nm,name1,name2,...)");
  if (table.columns[0].nm.empty())
    throwUserError(path, headerLine, 0, "no data rows after the header");
  return table;
}

namespace {

// Piecewise Gaussian with standard deviation 1/invLeft below mu, 1/invRight above.
float lobe(float x, float mu, float invLeft, float invRight) {
  const float t = (x - mu) * (x < mu ? invLeft : invRight);
  return std::exp(-0.5f * t * t);
}

}  // namespace

// Wyman, Sloan and Shirley 2013, the multi-lobe fit (their Listing 1 / Eq. 2).
float cieX(float l) {
  return 1.056f * lobe(l, 599.8f, 0.0264f, 0.0323f) + 0.362f * lobe(l, 442.0f, 0.0624f, 0.0374f) -
         0.065f * lobe(l, 501.1f, 0.0490f, 0.0382f);
}
float cieY(float l) {
  return 0.821f * lobe(l, 568.8f, 0.0213f, 0.0247f) + 0.286f * lobe(l, 530.9f, 0.0613f, 0.0322f);
}
float cieZ(float l) {
  return 1.217f * lobe(l, 437.0f, 0.0845f, 0.0278f) + 0.681f * lobe(l, 459.0f, 0.0385f, 0.0725f);
}

Rgb xyzToLinearSrgb(const Vec3& xyz) {
  return {3.2406f * xyz.x - 1.5372f * xyz.y - 0.4986f * xyz.z,
          -0.9689f * xyz.x + 1.8758f * xyz.y + 0.0415f * xyz.z,
          0.0557f * xyz.x - 0.2040f * xyz.y + 1.0570f * xyz.z};
}

namespace {

constexpr int kSteps = static_cast<int>(kCieMaxNm - kCieMinNm) + 1;  // 1 nm apart, ends included

float stepNm(int i) {
  return kCieMinNm + static_cast<float>(i);
}

// Trapezoid weights times (x̄, ȳ, z̄) at each step, computed once.
const std::array<Vec3, kSteps>& weightedCmf() {
  static const std::array<Vec3, kSteps> table = [] {
    std::array<Vec3, kSteps> t{};
    for (int i = 0; i < kSteps; ++i) {
      const float w = (i == 0 || i == kSteps - 1) ? 0.5f : 1.0f;
      const float l = stepNm(i);
      t[static_cast<size_t>(i)] = w * Vec3(cieX(l), cieY(l), cieZ(l));
    }
    return t;
  }();
  return table;
}

// ∫ value (x̄,ȳ,z̄) dλ for the samples values[i] at stepNm(i), summed in double.
Vec3 integrateXyz(const std::array<float, kSteps>& values) {
  glm::dvec3 xyz(0.0);
  for (size_t i = 0; i < values.size(); ++i)
    xyz += glm::dvec3(weightedCmf()[i]) * double(values[i]);
  return Vec3(xyz);
}

// sRGB of the samples, white-balanced so that all ones give (1,1,1).
Rgb samplesToRgb(const std::array<float, kSteps>& values) { return xyzToBalancedRgb(integrateXyz(values)); }

}  // namespace

Rgb xyzToBalancedRgb(const Vec3& xyz) {
  static const Rgb white = [] {
    std::array<float, kSteps> ones;
    ones.fill(1.0f);
    return xyzToLinearSrgb(integrateXyz(ones));
  }();
  return xyzToLinearSrgb(xyz) / white;
}

Rgb reflectanceToRgb(const Spectrum& s) {
  std::array<float, kSteps> v{};
  for (int i = 0; i < kSteps; ++i) v[static_cast<size_t>(i)] = s.at(stepNm(i));
  return samplesToRgb(v);
}

Rgb metalNormalReflectance(const Spectrum& n, const Spectrum& k) {
  std::array<float, kSteps> r{};
  for (int i = 0; i < kSteps; ++i) {
    const float ni = n.at(stepNm(i)), ki = k.at(stepNm(i));
    r[static_cast<size_t>(i)] = ((ni - 1) * (ni - 1) + ki * ki) / ((ni + 1) * (ni + 1) + ki * ki);
  }
  return samplesToRgb(r);
}

RgbToSpectrum::RgbToSpectrum(const std::string& path) : path_(path) {
  static constexpr const char* kNames[kBasisCount] = {"white", "cyan",  "magenta", "yellow",
                                                      "red",   "green", "blue"};
  SpectrumTable table = loadSpectraCsv(path);
  std::vector<std::string> missing;
  for (int b = 0; b < kBasisCount; ++b) {
    const auto it = std::find(table.names.begin(), table.names.end(), kNames[b]);
    if (it == table.names.end()) {
      missing.emplace_back(kNames[b]);
      continue;
    }
    Spectrum& column = table.columns[static_cast<size_t>(it - table.names.begin())];
    value_[b] = std::move(column.value);
    if (nm_.empty()) nm_ = std::move(column.nm);
  }
  if (!missing.empty())
    throwUserError(path, table.headerLine, 0,
                   "an RGB-to-spectrum table needs the columns white, cyan, magenta, yellow, "
                   "red, green, blue; missing: " +
                       joinNames(missing));
}

float RgbToSpectrum::eval(const Rgb& rgb, float lambdaNm) const {
  // Where lambdaNm falls: rows i0 and i1 = i0 + 1 (equal at and beyond the ends), weight t of i1.
  size_t i0 = 0, i1 = 0;
  float t = 0.0f;
  if (lambdaNm >= nm_.back()) {
    i0 = i1 = nm_.size() - 1;
  } else if (lambdaNm > nm_.front()) {
    i1 = static_cast<size_t>(std::upper_bound(nm_.begin(), nm_.end(), lambdaNm) - nm_.begin());
    i0 = i1 - 1;
    t = (lambdaNm - nm_[i0]) / (nm_[i1] - nm_[i0]);
  }
  const auto basis = [&](Basis which) {
    const std::vector<float>& v = value_[which];
    return v[i0] + t * (v[i1] - v[i0]);
  };

  // pbrt-v3 SampledSpectrum::FromRGB, SpectrumType::Reflectance (without its 0.94):
  // min * white + (mid - min) * secondary + (max - mid) * primary.
  const float r = std::max(rgb.r, 0.0f), g = std::max(rgb.g, 0.0f), b = std::max(rgb.b, 0.0f);
  float s = 0.0f;
  if (r <= g && r <= b) {  // red smallest
    s = r * basis(kWhite);
    if (g <= b)
      s += (g - r) * basis(kCyan) + (b - g) * basis(kBlue);
    else
      s += (b - r) * basis(kCyan) + (g - b) * basis(kGreen);
  } else if (g <= r && g <= b) {  // green smallest
    s = g * basis(kWhite);
    if (r <= b)
      s += (r - g) * basis(kMagenta) + (b - r) * basis(kBlue);
    else
      s += (b - g) * basis(kMagenta) + (r - b) * basis(kRed);
  } else {  // blue smallest
    s = b * basis(kWhite);
    if (r <= g)
      s += (r - b) * basis(kYellow) + (g - r) * basis(kGreen);
    else
      s += (g - b) * basis(kYellow) + (r - g) * basis(kRed);
  }
  return std::max(s, 0.0f);
}

const RgbToSpectrum& defaultRgbToSpectrum(const std::string& spectraDir) {
  static const RgbToSpectrum table(spectraDir + "/smits_rgb_to_spectrum.csv");
  assert(table.path() == spectraDir + "/smits_rgb_to_spectrum.csv");
  return table;
}

}  // namespace ll
