// A short path-traced measurement of how much each light-path class
// (render/light_path_class.h) contributes to a scene's picture: `path`
// renders the scene small, in independent batches (seeds seed, seed + 1,
// ...), each split by class. From the batches come each class's share of the
// picture and the relMSE the picture would have without a set of classes,
// both with 95 % confidence intervals. Used by `lightlab info`, by
// `path --set effects=measured` and by `lightlab study effects`.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "core/image.h"
#include "render/light_path_class.h"
#include "render/technique.h"

namespace ll {

// The relMSE below which leaving a light-path class out does not show: `lightlab info --tolerance` and
// `path --set effects_tolerance`. The README's "Which effects does a scene call for?" gives the study behind it.
inline constexpr double kDefaultEffectsTolerance = 1e-3;

// `params` with the two parameters of `--set effects=measured` (path, whitted, radiosity) appended:
// effects = all | measured, and effects_tolerance (relMSE). `measuredHelp` says what the technique leaves
// out and how it measures that.
std::vector<ParamDecl> withEffectsParams(std::vector<ParamDecl> params, const std::string& measuredHelp);

struct LightPathProbeSettings {
  int width = 128;              // pixels; the height keeps the camera's aspect ratio
  int sppPerBatch = 4;          // samples per pixel of one batch
  int batches = 64;             // batches rendered unless the time budget ends them sooner
  int minBatches = 4;           // batches rendered whatever the budget
  double budgetSeconds = 10.0;  // wall-clock limit of the path tracing
  uint64_t seed = 1;
};

// A value with its 95 % confidence interval.
struct Estimate {
  double value = 0.0, low = 0.0, high = 0.0;
};

class LightPathProbe {
 public:
  // Renders with `path` (a technique that splits by class) and `params`; progress(fraction) after each batch.
  LightPathProbe(const Scene& scene, const Accelerator& accel, const TechniqueInfo& path, const ParamSet& params,
                 const LightPathProbeSettings& settings, const std::function<void(double)>& progress = {});

  int width() const { return width_; }
  int height() const { return height_; }
  int batches() const { return static_cast<int>(batches_.size()); }
  int spp() const { return batches() * sppPerBatch_; }
  double seconds() const { return seconds_; }                // path tracing time of all batches
  double secondsPerPass() const { return seconds_ / spp(); }  // one sample per pixel

  // The class's share of the picture's luminance (summed over pixels), from 0 to 1.
  Estimate share(LightPathClass c) const;
  // relMSE (image_metrics.h) of the picture without these classes against the picture: mean over pixels and
  // channels of c^2 / (p^2 + 1e-2), c the classes' sum. c^2 is estimated without bias from pairs of
  // independent batches (the noise of one batch would otherwise count as error); the interval is the jackknife's.
  Estimate relMseWithout(LightPathMask classes) const;
  // The relMSE of a one-sample-per-pixel picture's noise against the picture: mean over pixels and channels of
  // the per-sample variance / (p^2 + 1e-2), from the spread of the batches. A render of n passes has 1/n of it.
  double noiseRelMsePerPass() const;
  // The mean of all batches: the picture, and one class of it.
  const Image& picture() const { return picture_; }
  Image classImage(LightPathClass c) const;

 private:
  int width_ = 0, height_ = 0, sppPerBatch_ = 1;
  double seconds_ = 0.0;
  std::vector<std::array<Image, kLightPathClassCount>> batches_;
  Image picture_;
};

// Student's t quantile t(0.975, dof): the half-width factor of a 95 % interval from `dof` degrees of freedom.
double studentT95(int dof);

}  // namespace ll
