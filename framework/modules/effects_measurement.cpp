#include "modules/effects_measurement.h"

#include <algorithm>
#include <cmath>

#include "modules/registry.h"
#include "render/render_job.h"

namespace ll {

namespace {

// The light-path class an effect is, if it is one.
std::optional<LightPathClass> classOf(Effect e) {
  for (int c = 0; c < kLightPathClassCount; ++c)
    if (lightPathClassEffect(lightPathClassAt(c)) == e) return lightPathClassAt(c);
  return std::nullopt;
}

nlohmann::json estimateJson(const Estimate& e) { return {{"value", e.value}, {"low", e.low}, {"high", e.high}}; }

}  // namespace

EffectsReport measureSceneEffects(const Scene& scene, const Accelerator& accel, double tolerance,
                                  const LightPathProbeSettings& settings,
                                  const std::function<void(const std::string&, double)>& progress) {
  EffectsReport r;
  r.tolerance = tolerance;
  r.seed = settings.seed;
  r.budgetSeconds = settings.budgetSeconds;

  // The probe: path tracing as it renders this scene best (spectral where the glass disperses).
  const TechniqueInfo& path = findTechnique("path");
  ParamSet pathParams(path.name, path.params);
  r.probeTechnique = "path";
  if (scene.effects.has(Effect::Dispersion)) {
    pathParams.set("spectral", "true");
    r.probeTechnique = "path --set spectral=true";
  }
  const LightPathProbe probe(scene, accel, path, pathParams, settings, [&](double f) {
    if (progress) progress("probe", f);
  });
  r.width = probe.width();
  r.height = probe.height();
  r.spp = probe.spp();
  r.batches = probe.batches();
  r.probeSeconds = probe.seconds();
  r.unseenPointLightCaustics =
      !scene.lights.empty() && (scene.hasMirrors || scene.hasTransmission);

  for (int i = 0; i < kEffectCount; ++i) {
    EffectMeasurement m;
    m.effect = static_cast<Effect>(1u << i);
    m.present = scene.effects.has(m.effect);
    if (const auto c = classOf(m.effect)) {
      m.measured = true;
      m.share = probe.share(*c);
      m.relMseWithout = probe.relMseWithout(lightPathBit(*c));
      m.calledFor = m.relMseWithout.high > tolerance;
    } else {
      m.calledFor = m.present;
    }
    r.effects.push_back(m);
  }

  // Each CPU technique: one pass at the probe's resolution, judged by what it leaves out.
  std::vector<const TechniqueInfo*> candidates;
  for (const TechniqueInfo& t : techniques())
    if (!t.gpu) candidates.push_back(&t);  // GPU techniques need a display
  for (size_t k = 0; k < candidates.size(); ++k) {
    const TechniqueInfo& t = *candidates[k];
    if (progress) progress(t.name, static_cast<double>(k) / static_cast<double>(candidates.size()));
    ParamSet params = &t == &path ? pathParams : ParamSet(t.name, t.params);
    if (params.has("intersection")) params.set("intersection", "framework");  // ray casting: the accelerator
    TechniqueVerdict v;
    v.technique = &t == &path ? r.probeTechnique : t.name;
    const EffectSet simulates = t.simulatesIn(scene, params);
    for (int c = 0; c < kLightPathClassCount; ++c)
      if (!simulates.has(lightPathClassEffect(lightPathClassAt(c)))) v.missedClasses |= lightPathBit(lightPathClassAt(c));
    v.missedError = probe.relMseWithout(v.missedClasses);
    for (int i = 0; i < kEffectCount; ++i) {
      const auto e = static_cast<Effect>(1u << i);
      if (scene.effects.has(e) && !classOf(e) && !simulates.has(e)) v.missedUnmeasured.add(e);
    }
    const auto technique = t.make();
    RenderSettings rs;
    rs.width = r.width;
    rs.height = r.height;
    rs.spp = 1;
    rs.seed = settings.seed;
    RenderJob job(scene, accel, *technique, params, rs);
    job.run();
    v.prepareSeconds = job.stats().prepareSeconds;
    v.secondsPerPass = job.stats().renderSeconds;
    if (&t == &path) {  // enough passes that its noise stays within half the tolerance (half is left for bias)
      const double passes = std::ceil(probe.noiseRelMsePerPass() / std::max(0.5 * tolerance, 1e-12));
      v.passes = static_cast<int>(std::clamp(passes, 1.0, 1e9));
    }
    const double pixelRatio = static_cast<double>(scene.camera.width) * scene.camera.height / (r.width * r.height);
    v.seconds = v.prepareSeconds + v.secondsPerPass * pixelRatio * v.passes;
    v.withinTolerance = v.missedUnmeasured.empty() && v.missedError.high <= tolerance;
    r.techniques.push_back(v);
  }
  if (progress) progress("techniques", 1.0);
  const TechniqueVerdict* best = nullptr;
  for (const TechniqueVerdict& v : r.techniques)
    if (v.withinTolerance && (!best || v.seconds < best->seconds)) best = &v;
  if (best) r.cheapest = best->technique;
  return r;
}

nlohmann::json EffectsReport::toJson() const {
  nlohmann::json effectsJson = nlohmann::json::array();
  for (const EffectMeasurement& m : effects) {
    nlohmann::json e = {{"effect", effectName(m.effect)}, {"present", m.present}, {"called_for", m.calledFor}};
    if (m.measured) {
      e["luminance_share"] = estimateJson(m.share);
      e["relmse_without"] = estimateJson(m.relMseWithout);
    } else {
      e["measured"] = false;  // not a light-path class: called for when present
    }
    effectsJson.push_back(e);
  }
  nlohmann::json techniquesJson = nlohmann::json::array();
  for (const TechniqueVerdict& v : techniques) {
    std::vector<std::string> missed;
    for (int c = 0; c < kLightPathClassCount; ++c)
      if (v.missedClasses & lightPathBit(lightPathClassAt(c))) missed.emplace_back(lightPathClassName(lightPathClassAt(c)));
    techniquesJson.push_back({{"technique", v.technique},
                              {"seconds_at_camera_resolution", v.seconds},
                              {"probe_prepare_seconds", v.prepareSeconds},
                              {"probe_seconds_per_pass", v.secondsPerPass},
                              {"passes", v.passes},
                              {"misses_classes", missed},
                              {"relmse_of_what_it_misses", estimateJson(v.missedError)},
                              {"misses_unmeasured", v.missedUnmeasured.names()},
                              {"within_tolerance", v.withinTolerance}});
  }
  return {{"tolerance_relmse", tolerance},
          {"probe",
           {{"technique", probeTechnique},
            {"width", width},
            {"height", height},
            {"spp", spp},
            {"batches", batches},
            {"seed", seed},
            {"seconds", probeSeconds},
            {"budget_seconds", budgetSeconds}}},
          {"effects", effectsJson},
          {"techniques", techniquesJson},
          {"cheapest_within_tolerance", cheapest ? nlohmann::json(*cheapest) : nlohmann::json(nullptr)},
          {"unseen_point_light_caustics", unseenPointLightCaustics}};
}

}  // namespace ll
