#include "modules/registry.h"

#include "core/error.h"
#include "core/timer.h"
#include "modules/module_list.h"

namespace ll {

#define LIGHTLAB_DECLARE_ACCELERATOR(fn) AcceleratorInfo fn();
#define LIGHTLAB_DECLARE_TECHNIQUE(fn) TechniqueInfo fn();
LIGHTLAB_ACCELERATORS(LIGHTLAB_DECLARE_ACCELERATOR)
LIGHTLAB_TECHNIQUES(LIGHTLAB_DECLARE_TECHNIQUE)

const std::vector<AcceleratorInfo>& accelerators() {
#define LIGHTLAB_LIST_ENTRY(fn) fn(),
  static const std::vector<AcceleratorInfo> kList = {LIGHTLAB_ACCELERATORS(LIGHTLAB_LIST_ENTRY)};
  return kList;
}

const std::vector<TechniqueInfo>& techniques() {
  static const std::vector<TechniqueInfo> kList = {LIGHTLAB_TECHNIQUES(LIGHTLAB_LIST_ENTRY)};
  return kList;
}

std::vector<std::string> acceleratorNames() {
  std::vector<std::string> names;
  for (const auto& a : accelerators()) names.push_back(a.name);
  return names;
}

std::vector<std::string> techniqueNames() {
  std::vector<std::string> names;
  for (const auto& t : techniques()) names.push_back(t.name);
  return names;
}

const AcceleratorInfo& findAccelerator(const std::string& name) {
  for (const auto& a : accelerators())
    if (a.name == name) return a;
  throwUserError("unknown accelerator '" + name + "' (known: " + joinNames(acceleratorNames()) + ")");
}

const TechniqueInfo& findTechnique(const std::string& name) {
  for (const auto& t : techniques())
    if (t.name == name) return t;
  throwUserError("unknown technique '" + name + "' (known: " + joinNames(techniqueNames()) + ")");
}

namespace {
// The cheapest CPU technique (GPU ones need a display) whose simulated effects `simulated(t)` contain `needed`.
template <typename Simulated>
const TechniqueInfo* cheapestWhere(EffectSet needed, Simulated simulated) {
  const TechniqueInfo* best = nullptr;
  for (const auto& t : techniques())
    if (!t.gpu && simulated(t).contains(needed) && (!best || t.cost < best->cost)) best = &t;
  return best;
}
}  // namespace

const TechniqueInfo* cheapestTechniqueFor(EffectSet needed) {
  return cheapestWhere(needed, [](const TechniqueInfo& t) { return t.simulates; });
}

const TechniqueInfo* cheapestTechniqueFor(const Scene& scene) {
  return cheapestWhere(scene.effects, [&](const TechniqueInfo& t) { return t.simulatesIn(scene); });
}

std::unique_ptr<Accelerator> buildAccelerator(const AcceleratorInfo& info, const ParamSet& params,
                                              const Geometry& geometry, double* buildSeconds) {
  auto accel = info.make(params);
  const Timer timer;
  accel->build(geometry);
  if (buildSeconds) *buildSeconds = timer.seconds();
  return accel;
}

}  // namespace ll
