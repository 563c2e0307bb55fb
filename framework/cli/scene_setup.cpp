#include "cli/scene_setup.h"

#include "core/error.h"
#include "core/timer.h"
#include "modules/registry.h"
#include "scene/scene_loader.h"

namespace ll::cli {

SceneSetup setUpScene(const std::string& scenePath, const std::string& technique, const std::string& accelerator,
                      const std::vector<std::string>& assignments) {
  SceneSetup s;
  s.technique = &findTechnique(technique);
  s.accelInfo = &findAccelerator(accelerator);
  s.techniqueParams = ParamSet("technique '" + technique + "'", s.technique->params);
  s.accelParams = ParamSet("accelerator '" + accelerator + "'", s.accelInfo->params);
  for (const std::string& a : assignments) {
    const std::string name = a.substr(0, a.find('='));
    if (s.techniqueParams.has(name) || !s.accelParams.has(name))
      s.techniqueParams.assign(a);  // reports unknown names with the technique's list
    else
      s.accelParams.assign(a);
  }
  const Timer load;
  s.scene = loadScene(scenePath);
  s.loadSeconds = load.seconds();
  s.accel = buildAccelerator(*s.accelInfo, s.accelParams, s.scene.geometry, &s.buildSeconds);
  return s;
}

}  // namespace ll::cli
