// lightlab study effects: per scene, the measured effect shares and every
// CPU technique's real error against path-traced ground truth, against its
// time (cli/effects_study.cpp).
#pragma once

#include <string>
#include <vector>

#include "render/light_path_probe.h"

namespace ll::cli {

struct EffectsStudyOptions {
  std::vector<std::string> scenes;  // empty: the bundled scenes the study names
  std::string out;                  // folder: effects.csv, effects.html
  double tolerance = kDefaultEffectsTolerance;
  int width = 96;                   // probe and renders, pixels
  int referenceSpp = 4096;          // the ground truth's samples per pixel
};

void runEffectsStudy(const EffectsStudyOptions& options, bool quiet);

}  // namespace ll::cli
