// lightlab info SCENE [--json]   |   lightlab info --list
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "core/error.h"
#include "modules/registry.h"
#include "scene/scene_loader.h"

namespace ll::cli {

namespace {

struct InfoOptions {
  std::string scene;
  bool json = false, list = false;
};

nlohmann::json vec(const Vec3& v) { return {v.x, v.y, v.z}; }

nlohmann::json describe(const Scene& s) {
  const TechniqueInfo* cheapest = cheapestTechniqueFor(s.effects);
  size_t point = 0, directional = 0;
  for (const Light& l : s.lights) (l.type == Light::Type::Point ? point : directional)++;
  const Bounds3 b = s.geometry.sceneBounds();
  nlohmann::json perTechnique = nlohmann::json::object();
  for (const TechniqueInfo& t : techniques()) {
    perTechnique[t.name] = {{"simulates", t.simulates.names()}, {"misses", s.effects.minus(t.simulates).names()}};
  }
  return {
      {"scene", s.path},
      {"camera",
       {{"eye", vec(s.camera.eye)},
        {"target", vec(s.camera.target)},
        {"up", vec(s.camera.up)},
        {"fov_y_deg", s.camera.fovYDeg},
        {"width", s.camera.width},
        {"height", s.camera.height}}},
      {"objects", s.objects.size()},
      {"materials", s.materials.size()},
      {"triangles", s.geometry.triangleCount()},
      {"spheres", s.geometry.spheres.size()},
      {"point_lights", point},
      {"directional_lights", directional},
      {"area_lights", s.areaLights.size()},
      {"sky", s.environment.black() ? "none" : s.environment.isImage() ? "image" : "constant"},
      {"bounds", {{"min", vec(b.min)}, {"max", vec(b.max)}}},
      {"effects", s.effects.names()},
      {"cheapest_technique", cheapest ? nlohmann::json(cheapest->name) : nlohmann::json(nullptr)},
      {"techniques", perTechnique},
  };
}

void printList() {
  std::printf("techniques:\n");
  for (const TechniqueInfo& t : techniques()) {
    std::printf("  %-16s %s\n", t.name.c_str(), t.help.c_str());
    std::printf("  %-16s simulates: %s\n", "", joinNames(t.simulates.names()).c_str());
    for (const ParamDecl& p : t.params)
      std::printf("  %-16s --set %s=%s  (%s %s) %s\n", "", p.name.c_str(), p.defaultValue.c_str(),
                  p.typeName().c_str(), p.rangeText().c_str(), p.help.c_str());
  }
  std::printf("accelerators:\n");
  for (const AcceleratorInfo& a : accelerators()) {
    std::printf("  %-16s %s\n", a.name.c_str(), a.help.c_str());
    for (const ParamDecl& p : a.params)
      std::printf("  %-16s --set %s=%s  (%s %s) %s\n", "", p.name.c_str(), p.defaultValue.c_str(),
                  p.typeName().c_str(), p.rangeText().c_str(), p.help.c_str());
  }
}

}  // namespace

Command addInfoCommand(CLI::App& app, const GlobalOptions&) {
  auto o = std::make_shared<InfoOptions>();
  CLI::App* cmd = app.add_subcommand("info", "Describe a scene: content, effects it calls for, cheapest technique");
  cmd->add_option("scene", o->scene, "Scene file (.json or .obj)");
  cmd->add_flag("--json", o->json, "Print JSON instead of text");
  cmd->add_flag("--list", o->list, "List the registered techniques and accelerators with their parameters");
  return [o]() {
    if (o->list) return printList();
    if (o->scene.empty()) throwUserError("info: give a SCENE file, or --list");
    const Scene scene = loadScene(o->scene);
    const nlohmann::json j = describe(scene);
    if (o->json) {
      std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
      return;
    }
    std::printf("scene      %s\n", scene.path.c_str());
    std::printf("content    %zu objects, %u triangles, %zu spheres, %zu materials\n", scene.objects.size(),
                scene.geometry.triangleCount(), scene.geometry.spheres.size(), scene.materials.size());
    std::printf("lights     %zu point/directional, %zu area (emissive objects), sky: %s\n", scene.lights.size(),
                scene.areaLights.size(),
                scene.environment.black()     ? "none (black background)"
                : scene.environment.isImage() ? "an HDR image (a light for path)"
                                              : "a constant colour (a light for path)");
    std::printf("camera     %dx%d, fov %.2f deg\n", scene.camera.width, scene.camera.height,
                static_cast<double>(scene.camera.fovYDeg));
    std::printf("effects    %s\n", joinNames(scene.effects.names()).c_str());
    const TechniqueInfo* cheapest = cheapestTechniqueFor(scene.effects);
    std::printf("cheapest   %s\n",
                cheapest ? cheapest->name.c_str() : "(no registered technique simulates all of these effects)");
    for (const TechniqueInfo& t : techniques()) {
      const EffectSet missed = scene.effects.minus(t.simulates);
      std::string line = missed.empty() ? "simulates all" : "misses " + joinNames(missed.names());
      for (const TechniqueInfo::ParamEffect& e : t.onlyWith) {  // "path ... dispersion: with --set spectral=true"
        const EffectSet needs = EffectSet::fromBits(scene.effects.bits() & e.effects.bits());
        if (!needs.empty()) line += " (" + joinNames(needs.names()) + ": with --set " + e.param + "=" + e.value + ")";
      }
      std::printf("  %-16s %s\n", t.name.c_str(), line.c_str());
    }
  };
}

}  // namespace ll::cli
