// lightlab info SCENE [--json] [--tolerance R] [--budget S] [--no-probe]   |   lightlab info --list
//
// A scene's content, the effects it makes possible ("present"), and -- from a
// short seeded path-traced probe (modules/effects_measurement.h) -- the
// effects it calls for, measured, with the cheapest technique within the
// tolerance.
#include <cmath>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "core/error.h"
#include "core/progress.h"
#include "modules/effects_measurement.h"
#include "modules/registry.h"
#include "scene/scene_loader.h"

namespace ll::cli {

namespace {

struct InfoOptions {
  std::string scene;
  bool json = false, list = false, noProbe = false;
  double tolerance = kDefaultEffectsTolerance;
  LightPathProbeSettings probe;
};

// "33.1 % (32.8-33.4)": a share with its 95 % interval.
std::string percent(const Estimate& e) {
  char buf[96];
  if (e.high <= 0.0) return "0";
  std::snprintf(buf, sizeof buf, "%.3g %% (%.3g-%.3g)", 100.0 * e.value, 100.0 * e.low, 100.0 * e.high);
  return buf;
}

std::string relMse(const Estimate& e) {
  char buf[96];
  if (e.high <= 0.0) return "0";
  std::snprintf(buf, sizeof buf, "%.2g (%.2g-%.2g)", e.value, e.low, e.high);
  return buf;
}

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, s < 10.0 ? "%.2g s" : "%.0f s", s);
  return buf;
}

void printMeasurement(const EffectsReport& r, int camWidth, int camHeight) {
  std::printf("\nmeasured   %s, %dx%d px, %d spp (%d batches of %d), seed %llu: %.1f s (budget %.0f s)\n",
              r.probeTechnique.c_str(), r.width, r.height, r.spp, r.batches, r.spp / std::max(1, r.batches),
              static_cast<unsigned long long>(r.seed), r.probeSeconds, r.budgetSeconds);
  std::printf("           an effect is called for when the picture without it differs by more than relMSE %g\n",
              r.tolerance);
  std::printf("  %-24s %-24s %-24s %s\n", "effect", "share of the light", "relMSE without it", "called for");
  std::string unmeasured;
  for (const EffectMeasurement& m : r.effects) {
    if (!m.measured) {
      if (m.present) unmeasured += std::string(unmeasured.empty() ? "" : ", ") + effectName(m.effect);
      continue;
    }
    if (!m.present && m.share.high <= 0.0) continue;
    std::printf("  %-24s %-24s %-24s %s\n", effectName(m.effect), percent(m.share).c_str(),
                relMse(m.relMseWithout).c_str(), m.calledFor ? "yes" : "no");
  }
  for (const EffectMeasurement& m : r.effects)
    if (m.effect == Effect::Emission && m.measured && m.share.high > 0.0)
      std::printf("  (emission: the lights, and the sky or backdrop, seen directly or through mirrors and glass)\n");
  if (!unmeasured.empty())
    std::printf("  not light paths, called for as present: %s\n", unmeasured.c_str());
  if (r.unseenPointLightCaustics)
    std::printf("  caustics of the point and directional lights are not measured: a path tracer cannot find light\n"
                "  from a point through mirrors or glass onto a surface (L S+ D; whitted's filtered shadow rays\n"
                "  approximate it, unfocused)\n");
  const auto occurs = [&](Effect e) {  // the probe found light of this class
    for (const EffectMeasurement& m : r.effects)
      if (m.effect == e) return m.share.high > 0.0;
    return false;
  };
  std::printf("\n  %-26s %-22s %-27s %s\n", "technique", "time", "relMSE of what it misses", "within tolerance");
  for (const TechniqueVerdict& v : r.techniques) {
    std::string time = seconds(v.seconds);
    if (v.passes > 1) time += " (" + std::to_string(v.passes) + " passes)";
    std::string verdict = v.withinTolerance ? "yes" : "no";
    std::vector<std::string> missed;
    for (int c = 0; c < kLightPathClassCount; ++c)
      if ((v.missedClasses & lightPathBit(lightPathClassAt(c))) && occurs(lightPathClassEffect(lightPathClassAt(c))))
        missed.emplace_back(lightPathClassName(lightPathClassAt(c)));
    if (!missed.empty()) verdict += ": misses " + joinNames(missed);
    if (!v.missedUnmeasured.empty())
      verdict += std::string(missed.empty() ? ": misses " : "; also ") + joinNames(v.missedUnmeasured.names());
    std::printf("  %-26s %-22s %-27s %s\n", v.technique.c_str(), time.c_str(), relMse(v.missedError).c_str(),
                verdict.c_str());
  }
  std::printf("  (time: for the camera's %dx%d picture, estimated from one pass measured at the probe's size with a "
              "BVH, preparation included;\n   path: the passes that bring its noise within half the tolerance. What it "
              "misses: the light paths it cannot follow;\n   its own model's differences, such as the ambient term, are "
              "not counted: `lightlab study effects` measures them)\n", camWidth, camHeight);
  std::printf("cheapest   %s\n", r.cheapest ? (r.cheapest->c_str() + std::string(" (the fastest within relMSE ") +
                                                 std::to_string(r.tolerance).substr(0, 6) + ")").c_str()
                                            : "(no technique stays within the tolerance)");
}

nlohmann::json vec(const Vec3& v) { return {v.x, v.y, v.z}; }

nlohmann::json describe(const Scene& s) {
  const TechniqueInfo* cheapest = cheapestTechniqueFor(s);
  size_t point = 0, directional = 0;
  for (const Light& l : s.lights) (l.type == Light::Type::Point ? point : directional)++;
  const Bounds3 b = s.geometry.sceneBounds();
  nlohmann::json perTechnique = nlohmann::json::object();
  for (const TechniqueInfo& t : techniques()) {
    const EffectSet simulates = t.simulatesIn(s);
    perTechnique[t.name] = {{"simulates", simulates.names()}, {"misses", s.effects.minus(simulates).names()}};
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

Command addInfoCommand(CLI::App& app, const GlobalOptions& global) {
  auto o = std::make_shared<InfoOptions>();
  CLI::App* cmd = app.add_subcommand("info", "Describe a scene: content, effects it calls for, cheapest technique");
  cmd->add_option("scene", o->scene, "Scene file (.json or .obj)");
  cmd->add_flag("--json", o->json, "Print JSON instead of text");
  cmd->add_flag("--list", o->list, "List the registered techniques and accelerators with their parameters");
  cmd->add_option("--tolerance", o->tolerance,
                  "relMSE a left-out effect may change the picture by and not be called for")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--budget", o->probe.budgetSeconds, "Seconds the path-traced probe may take (at least 4 batches)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 3600.0));
  cmd->add_option("--probe-width", o->probe.width, "Width of the probe in pixels (height: the camera's aspect)")
      ->capture_default_str()
      ->check(CLI::Range(8, 1024));
  cmd->add_option("--seed", o->probe.seed, "Seed of the probe")->capture_default_str();
  cmd->add_flag("--no-probe", o->noProbe, "Only the content and the effects present (no measurement)");
  return [o, &global]() {
    if (o->list) return printList();
    if (o->scene.empty()) throwUserError("info: give a SCENE file, or --list");
    const Scene scene = loadScene(o->scene);
    nlohmann::json j = describe(scene);
    std::optional<EffectsReport> report;
    if (!o->noProbe) {
      const AcceleratorInfo& a = findAccelerator("bvh");
      const auto accel = buildAccelerator(a, ParamSet(a.name, a.params), scene.geometry);
      setPrecomputationCache(false);  // each technique's time includes its own precomputation (radiosity's solve)
      ProgressBar bar("info: measuring effects", 1.0, global.quiet || o->json);
      report = measureSceneEffects(scene, *accel, o->tolerance, o->probe, [&](const std::string& phase, double f) {
        bar.update(phase == "probe" ? 0.5 * f : 0.5 + 0.5 * f);
      });
      bar.finish();
      j["measured"] = report->toJson();
    }
    if (o->json) {
      std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
      return;
    }
    std::printf("scene      %s\n", scene.path.c_str());
    std::printf("content    %zu objects, %u triangles, %zu spheres, %zu materials\n", scene.objects.size(),
                scene.geometry.triangleCount(), scene.geometry.spheres.size(), scene.materials.size());
    std::printf("lights     %zu point/directional, %zu area (emissive objects), sky: %s\n", scene.lights.size(),
                scene.areaLights.size(),
                scene.environment.black() ? "none (black background)"
                : !scene.environment.lightsScene()
                    ? (scene.environment.isImage() ? "an HDR image, a backdrop that lights nothing"
                                                   : "a constant colour, a backdrop that lights nothing")
                : scene.environment.isImage() ? "an HDR image (a light for path)"
                                              : "a constant colour (a light for path)");
    std::printf("camera     %dx%d, fov %.2f deg\n", scene.camera.width, scene.camera.height,
                static_cast<double>(scene.camera.fovYDeg));
    std::printf("present    %s\n", joinNames(scene.effects.names()).c_str());
    std::printf("           (the effects the scene's content makes possible, whatever their size)\n");
    const TechniqueInfo* cheapest = cheapestTechniqueFor(scene);
    std::printf("simulates all present: %s\n",
                cheapest ? cheapest->name.c_str() : "(no registered technique simulates all of these effects)");
    for (const TechniqueInfo& t : techniques()) {
      const EffectSet missed = scene.effects.minus(t.simulatesIn(scene));
      std::string line = (missed.empty() ? "simulates all" : "misses " + joinNames(missed.names())) + t.lightsNote(scene);
      for (const TechniqueInfo::ParamEffect& e : t.onlyWith) {  // "path ... dispersion: with --set spectral=true"
        const EffectSet needs = EffectSet::fromBits(scene.effects.bits() & e.effects.bits());
        if (!needs.empty()) line += " (" + joinNames(needs.names()) + ": with --set " + e.param + "=" + e.value + ")";
      }
      std::printf("  %-16s %s\n", t.name.c_str(), line.c_str());
    }
    if (report) printMeasurement(*report, scene.camera.width, scene.camera.height);
  };
}

}  // namespace ll::cli
