// What render, trace and (later) the GUI share: load a scene, pick a
// technique and accelerator by name, route --set name=value to whichever
// declares the parameter, and build the accelerator -- timing each phase.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accel/accelerator.h"
#include "render/technique.h"
#include "scene/scene.h"

namespace ll::cli {

struct SceneSetup {
  Scene scene;
  const TechniqueInfo* technique = nullptr;
  const AcceleratorInfo* accelInfo = nullptr;
  ParamSet techniqueParams, accelParams;
  std::unique_ptr<Accelerator> accel;
  double loadSeconds = 0.0, buildSeconds = 0.0;
};

// Throws UserError for unknown names, bad --set assignments or a bad scene.
// Names are resolved before the scene is loaded, so typos fail fast.
SceneSetup setUpScene(const std::string& scenePath, const std::string& technique, const std::string& accelerator,
                      const std::vector<std::string>& assignments);

}  // namespace ll::cli
