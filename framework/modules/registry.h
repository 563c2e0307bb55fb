// Lookup of techniques and accelerators by name. Unknown names are user
// errors that list the known ones.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accel/accelerator.h"
#include "render/technique.h"

namespace ll {

const std::vector<AcceleratorInfo>& accelerators();
const std::vector<TechniqueInfo>& techniques();
const AcceleratorInfo& findAccelerator(const std::string& name);
const TechniqueInfo& findTechnique(const std::string& name);

std::vector<std::string> acceleratorNames();
std::vector<std::string> techniqueNames();

// The cheapest technique that simulates every effect in `needed`, or null.
const TechniqueInfo* cheapestTechniqueFor(EffectSet needed);
// ... that simulates every effect the scene has, with its lights (techniques' simulatesIn).
const TechniqueInfo* cheapestTechniqueFor(const Scene& scene);

// Builds the named accelerator over the scene (with its parameters).
std::unique_ptr<Accelerator> buildAccelerator(const AcceleratorInfo& info, const ParamSet& params,
                                              const Geometry& geometry, double* buildSeconds = nullptr);

}  // namespace ll
