#include "scene/named_metals.h"

#include <cstdlib>
#include <map>
#include <mutex>

#include "core/error.h"
#include "core/spectrum.h"

namespace ll {

namespace {

struct MetalFile {
  const char* name;
  const char* file;
};
constexpr MetalFile kMetals[] = {
    {"aluminium", "metal_al.csv"}, {"copper", "metal_cu.csv"}, {"gold", "metal_au.csv"}, {"silver", "metal_ag.csv"}};

MetalIndex readMetal(const std::string& path) {
  const SpectrumTable table = loadSpectraCsv(path);
  const Spectrum* n = nullptr;
  const Spectrum* k = nullptr;
  for (size_t i = 0; i < table.names.size(); ++i) {
    if (table.names[i] == "n") n = &table.columns[i];
    if (table.names[i] == "k") k = &table.columns[i];
  }
  if (n == nullptr || k == nullptr) throw UserError(path + ":1: a metal's table needs the columns n and k");
  return {reflectanceToRgb(*n), reflectanceToRgb(*k), path, std::make_shared<const Spectrum>(*n),
          std::make_shared<const Spectrum>(*k)};
}

}  // namespace

const std::vector<std::string>& metalNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const MetalFile& m : kMetals) v.emplace_back(m.name);
    return v;
  }();
  return names;
}

std::string spectraDirectory() {
  if (const char* dir = std::getenv("LIGHTLAB_SPECTRA_DIR"); dir != nullptr && *dir != '\0') return dir;
  return LIGHTLAB_DEFAULT_SPECTRA_DIR;
}

std::optional<MetalIndex> namedMetal(const std::string& name) {
  static std::mutex mutex;
  static std::map<std::string, MetalIndex> cache;
  for (const MetalFile& m : kMetals) {
    if (name != m.name) continue;
    const std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(name);
    if (it == cache.end()) it = cache.emplace(name, readMetal(spectraDirectory() + "/" + m.file)).first;
    return it->second;
  }
  return std::nullopt;
}

}  // namespace ll
