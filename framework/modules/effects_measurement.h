// Which effects a scene calls for, measured (`lightlab info`, `lightlab
// study effects`): a light-path probe (render/light_path_probe.h) gives each
// effect that is a light-path class its share of the picture and the relMSE
// of the picture without it; an effect is called for when that relMSE's 95 %
// upper bound exceeds the tolerance. Every registered CPU technique is then
// timed on the probe's resolution and judged by the relMSE of the classes it
// misses; the cheapest one within the tolerance is named.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/light_path_probe.h"
#include "scene/scene.h"

namespace ll {

struct EffectMeasurement {
  Effect effect{};
  bool present = false;   // the scene's content makes it possible (scene.effects)
  bool measured = false;  // a light-path class: share and relMSE below are set
  Estimate share;         // of the picture's luminance, 0..1
  Estimate relMseWithout;
  bool calledFor = false;  // measured: relMseWithout.high > tolerance; otherwise: present
};

struct TechniqueVerdict {
  std::string technique;  // with the parameter it needs, e.g. "path --set spectral=true"
  double prepareSeconds = 0.0;  // measured: what it does once per picture (radiosity's solve)
  double secondsPerPass = 0.0;  // measured: one pass at the probe's resolution
  int passes = 1;               // passes that bring its noise within half the tolerance (path); 1 for the others
  // The picture at the camera's resolution, estimated: preparation + one pass x the ratio of pixels x passes.
  double seconds = 0.0;
  LightPathMask missedClasses = 0;  // light-path classes whose effect it does not simulate
  Estimate missedError;             // relMSE of the picture without them (probe)
  EffectSet missedUnmeasured;       // present effects it misses that are not light-path classes
  bool withinTolerance = false;
};

struct EffectsReport {
  double tolerance = 0.0;
  int width = 0, height = 0, spp = 0, batches = 0;
  uint64_t seed = 0;
  double probeSeconds = 0.0, budgetSeconds = 0.0;
  std::string probeTechnique;  // "path" or "path --set spectral=true"
  std::vector<EffectMeasurement> effects;  // every effect the framework names, in Effect order
  std::vector<TechniqueVerdict> techniques;
  std::optional<std::string> cheapest;  // a TechniqueVerdict::technique
  // Point or directional lights and mirrors or glass: light from a light of zero size through a specular chain
  // onto a surface (L S+ D) has probability zero for a path tracer, so those caustics are not in the probe.
  bool unseenPointLightCaustics = false;

  nlohmann::json toJson() const;
};

// Measures `scene` (accelerated by `accel`). progress(label, fraction) reports the phases (probe, each technique).
EffectsReport measureSceneEffects(const Scene& scene, const Accelerator& accel, double tolerance,
                                  const LightPathProbeSettings& probe,
                                  const std::function<void(const std::string&, double)>& progress = {});

}  // namespace ll
