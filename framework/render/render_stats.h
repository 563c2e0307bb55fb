// Statistics of one render: time by phase, rays by kind, accelerator work,
// non-finite samples caught, and student tasks found missing.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "accel/accelerator.h"
#include "core/ray.h"
#include "render/light_path_split.h"

namespace ll {

// Counters one worker accumulates without synchronisation.
struct WorkCounters {
  std::array<uint64_t, kRayKindCount> rays{};
  QueryCounters query;
  uint64_t nonFinite = 0;  // samples that were NaN/Inf and were replaced by 0
  void add(const WorkCounters& o) {
    for (int i = 0; i < kRayKindCount; ++i) rays[static_cast<size_t>(i)] += o.rays[static_cast<size_t>(i)];
    query.add(o.query);
    nonFinite += o.nonFinite;
  }
  uint64_t totalRays() const {
    uint64_t n = 0;
    for (uint64_t r : rays) n += r;
    return n;
  }
};

// What a technique left out because a short measurement said it does not
// show (--set effects=measured), and what that saved and cost.
struct SkippedWork {
  std::string skipped;            // the classes left out, by name ("diffuse-interreflection, caustics")
  LightPathMask leftOut = 0;      // ... as a mask (includes classes the scene does not produce)
  double tolerance = 0.0;         // relMSE the skipped classes were allowed
  double errorAdded = 0.0;        // relMSE of the picture without them, measured by the probe
  double errorAddedHigh = 0.0;    // its 95 % upper confidence bound
  double probeSeconds = 0.0;      // the measurement's own time
  double secondsPerPassFull = 0.0, secondsPerPassSkipping = 0.0;  // one pass of the probe, without and with skipping
  std::string saved;  // what was saved where it is counted, not timed (radiosity: hemicube rows not computed)
};

struct RenderStats {
  std::string technique, accelerator, scene;
  int width = 0, height = 0, spp = 0, passes = 0;
  double loadSeconds = 0.0, buildSeconds = 0.0, prepareSeconds = 0.0, renderSeconds = 0.0;
  AcceleratorStats accel;
  WorkCounters work;
  bool cancelled = false;
  std::map<std::string, std::string> missingTasks;  // task id -> what
  std::set<std::string> exactFallbacks;             // of those, the ones whose fallback changes nothing but time
  std::map<std::string, std::string> taskViolations;  // task id -> the rule its code broke
  std::string referenceTasks;                       // tasks run by their reference (--reference), "A2.3,A2.5"
  std::optional<SkippedWork> skipped;               // --set effects=measured: what the technique left out
  std::vector<LightPathShare> lightPaths;           // each light-path class's share, where the render kept them

  nlohmann::json toJson() const;
};

}  // namespace ll
