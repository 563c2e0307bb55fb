#include "render/render_stats.h"

#include <nlohmann/json.hpp>

namespace ll {

nlohmann::json RenderStats::toJson() const {
  nlohmann::json rayCounts = nlohmann::json::object();
  for (int i = 0; i < kRayKindCount; ++i)
    rayCounts[std::string(kRayKindNames[static_cast<size_t>(i)])] = work.rays[static_cast<size_t>(i)];
  rayCounts["total"] = work.totalRays();
  const double seconds = renderSeconds > 0.0 ? renderSeconds : 1e-9;
  nlohmann::json classes = nlohmann::json::object();
  for (const LightPathShare& s : lightPaths)
    classes[lightPathClassName(s.cls)] = {{"pattern", lightPathClassPattern(s.cls)},
                                          {"luminance_share", s.luminanceShare},
                                          {"relmse_without", s.relMseWithout}};
  return {
      {"scene", scene},
      {"technique", technique},
      {"accelerator", accelerator},
      {"width", width},
      {"height", height},
      {"spp", spp},
      {"passes", passes},
      {"cancelled", cancelled},
      {"time_seconds",
       {{"load", loadSeconds}, {"build", buildSeconds}, {"prepare", prepareSeconds}, {"render", renderSeconds}}},
      {"rays", rayCounts},
      {"mrays_per_second", static_cast<double>(work.totalRays()) / seconds * 1e-6},
      {"accelerator_stats",
       {{"build_seconds", accel.buildSeconds},
        {"memory_bytes", accel.memoryBytes},
        {"nodes", accel.nodeCount},
        {"depth", accel.depth},
        {"sah_cost", accel.sahCost},
        {"nodes_visited", work.query.nodesVisited},
        {"primitives_tested", work.query.primitivesTested}}},
      {"non_finite_samples", work.nonFinite},
      {"missing_tasks", missingTasks},
      {"exact_fallbacks", exactFallbacks},
      {"task_violations", taskViolations},
      {"reference_tasks", referenceTasks},
      {"light_paths", lightPaths.empty() ? nlohmann::json(nullptr) : classes},
      {"skipped", skipped ? nlohmann::json{{"what", skipped->skipped},
                                           {"tolerance_relmse", skipped->tolerance},
                                           {"error_added_relmse", skipped->errorAdded},
                                           {"error_added_relmse_95", skipped->errorAddedHigh},
                                           {"probe_seconds", skipped->probeSeconds},
                                           {"probe_seconds_per_pass_full", skipped->secondsPerPassFull},
                                           {"probe_seconds_per_pass_skipping", skipped->secondsPerPassSkipping},
                                           {"time_saved_fraction",
                                            skipped->secondsPerPassFull > 0
                                                ? 1.0 - skipped->secondsPerPassSkipping / skipped->secondsPerPassFull
                                                : 0.0},
                                           {"saved", skipped->saved}}
                          : nlohmann::json(nullptr)},
  };
}

}  // namespace ll
