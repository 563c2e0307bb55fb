#include "render/light_path_probe.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/math.h"
#include "metrics/image_metrics.h"
#include "core/timer.h"
#include "render/render_job.h"

namespace ll {

double studentT95(int dof) {
  static constexpr double kTable[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                      2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                      2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  if (dof < 1) return 0.0;
  if (dof <= 30) return kTable[dof - 1];
  return 1.96 + 2.4 / dof;  // within 0.2 % of the quantile above 30
}

namespace {

double luminanceSum(const Image& image) {
  double sum = 0.0;
  for (const Rgb& p : image.pixels()) sum += static_cast<double>(luminance(p));
  return sum;
}

Estimate meanInterval(const std::vector<double>& values) {
  const auto n = static_cast<double>(values.size());
  double mean = 0.0;
  for (double v : values) mean += v;
  mean /= n;
  double var = 0.0;
  for (double v : values) var += (v - mean) * (v - mean);
  const double half = values.size() > 1 ? studentT95(static_cast<int>(values.size()) - 1) * std::sqrt(var / (n - 1) / n) : 0.0;
  return {mean, mean - half, mean + half};
}

}  // namespace

LightPathProbe::LightPathProbe(const Scene& scene, const Accelerator& accel, const TechniqueInfo& path,
                               const ParamSet& params, const LightPathProbeSettings& settings,
                               const std::function<void(double)>& progress)
    : sppPerBatch_(std::max(1, settings.sppPerBatch)) {
  width_ = std::max(8, settings.width);
  height_ = std::max(8, width_ * scene.camera.height / std::max(1, scene.camera.width));
  const std::unique_ptr<Technique> technique = path.make();
  if (!technique->splitsLightPaths()) throwUserError("the light-path probe needs a technique that splits by class");
  const Timer timer;
  const int most = std::max(settings.batches, settings.minBatches);
  for (int b = 0; b < most; ++b) {
    RenderSettings rs;
    rs.width = width_;
    rs.height = height_;
    rs.spp = sppPerBatch_;
    rs.seed = settings.seed + static_cast<uint64_t>(b);
    rs.lightPaths = true;
    RenderJob job(scene, accel, *technique, params, rs);
    job.run();
    std::array<Image, kLightPathClassCount> classes;
    for (int c = 0; c < kLightPathClassCount; ++c) classes[static_cast<size_t>(c)] = job.frame().resolveLightPath(lightPathClassAt(c));
    batches_.push_back(std::move(classes));
    seconds_ += job.stats().renderSeconds + job.stats().prepareSeconds;
    if (progress) progress(static_cast<double>(b + 1) / most);
    if (b + 1 >= settings.minBatches && timer.seconds() > settings.budgetSeconds) break;
  }
  picture_ = Image(width_, height_);
  for (int c = 0; c < kLightPathClassCount; ++c) {
    const Image image = classImage(lightPathClassAt(c));
    for (size_t i = 0; i < image.pixels().size(); ++i) picture_.pixels()[i] += image.pixels()[i];
  }
}

Image LightPathProbe::classImage(LightPathClass c) const {
  Image mean(width_, height_);
  for (const auto& batch : batches_) {
    const Image& image = batch[static_cast<size_t>(c)];
    for (size_t i = 0; i < image.pixels().size(); ++i) mean.pixels()[i] += image.pixels()[i];
  }
  const float n = static_cast<float>(batches_.size());
  for (Rgb& p : mean.pixels()) p /= n;
  return mean;
}

double LightPathProbe::noiseRelMsePerPass() const {
  const size_t k = batches_.size();
  if (k < 2) return 0.0;
  std::vector<Image> sums;  // each batch's picture
  for (const auto& batch : batches_) {
    Image sum(width_, height_);
    for (const Image& image : batch)
      for (size_t i = 0; i < image.pixels().size(); ++i) sum.pixels()[i] += image.pixels()[i];
    sums.push_back(std::move(sum));
  }
  double total = 0.0;
  for (size_t i = 0; i < picture_.pixels().size(); ++i)
    for (int ch = 0; ch < 3; ++ch) {
      const auto p = static_cast<double>(picture_.pixels()[i][ch]);
      double var = 0.0;
      for (const Image& s : sums) var += (static_cast<double>(s.pixels()[i][ch]) - p) * (static_cast<double>(s.pixels()[i][ch]) - p);
      total += var / static_cast<double>(k - 1) * relMseWeight(p);
    }
  // A batch's variance is the per-sample variance over sppPerBatch samples.
  return total / static_cast<double>(3 * picture_.pixels().size()) * sppPerBatch_;
}

Estimate LightPathProbe::share(LightPathClass c) const {
  std::vector<double> shares;
  for (const auto& batch : batches_) {
    double total = 0.0;
    for (const Image& image : batch) total += luminanceSum(image);
    shares.push_back(total > 0.0 ? luminanceSum(batch[static_cast<size_t>(c)]) / total : 0.0);
  }
  Estimate e = meanInterval(shares);
  e.low = std::max(0.0, e.low);
  e.high = std::min(1.0, e.high);
  return e;
}

Estimate LightPathProbe::relMseWithout(LightPathMask classes) const {
  const size_t k = batches_.size(), n = static_cast<size_t>(width_) * static_cast<size_t>(height_) * 3;
  if (k < 2) throwUserError("the light-path probe needs two batches or more");
  // Per batch and pixel channel, the classes' sum c_b; S = sum_b c_b, Q = sum_b c_b^2.
  std::vector<std::vector<double>> c(k, std::vector<double>(n, 0.0));
  for (size_t b = 0; b < k; ++b)
    for (int cls = 0; cls < kLightPathClassCount; ++cls) {
      if (!(classes & lightPathBit(lightPathClassAt(cls)))) continue;
      const std::vector<Rgb>& px = batches_[b][static_cast<size_t>(cls)].pixels();
      for (size_t i = 0; i < px.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) c[b][i * 3 + static_cast<size_t>(ch)] += static_cast<double>(px[i][ch]);
    }
  std::vector<double> s(n, 0.0), q(n, 0.0), weight(n);
  for (size_t i = 0; i < n; ++i) {
    const auto p = static_cast<double>(picture_.pixels()[i / 3][static_cast<int>(i % 3)]);
    weight[i] = relMseWeight(p) / static_cast<double>(n);
    for (size_t b = 0; b < k; ++b) {
      s[i] += c[b][i];
      q[i] += c[b][i] * c[b][i];
    }
  }
  // The mean of c_a c_b over pairs a != b estimates c^2 without the noise variance.
  const auto estimate = [&](size_t leftOut) {
    const double m = static_cast<double>(leftOut < k ? k - 1 : k);
    double sum = 0.0;
    for (size_t i = 0; i < n; ++i) {
      double si = s[i], qi = q[i];
      if (leftOut < k) {
        si -= c[leftOut][i];
        qi -= c[leftOut][i] * c[leftOut][i];
      }
      sum += (si * si - qi) / (m * (m - 1.0)) * weight[i];
    }
    return sum;
  };
  const double all = estimate(k);
  if (k < 3) return {std::max(0.0, all), 0.0, std::max(0.0, all)};
  double mean = 0.0;
  std::vector<double> jack(k);
  for (size_t b = 0; b < k; ++b) mean += (jack[b] = estimate(b));
  mean /= static_cast<double>(k);
  double var = 0.0;
  for (double j : jack) var += (j - mean) * (j - mean);
  const double half = studentT95(static_cast<int>(k) - 1) *
                      std::sqrt(var * (static_cast<double>(k) - 1.0) / static_cast<double>(k));
  return {std::max(0.0, all), std::max(0.0, all - half), std::max(0.0, all + half)};
}

std::vector<ParamDecl> withEffectsParams(std::vector<ParamDecl> params, const std::string& measuredHelp) {
  params.push_back(ParamDecl::choice("effects", "all", {"all", "measured"},
                                     "all: everything the scene calls for; measured: " + measuredHelp));
  params.push_back(ParamDecl::real("effects_tolerance", kDefaultEffectsTolerance, 0.0, 1.0,
                                   "effects=measured: the relMSE what is left out may add"));
  return params;
}

}  // namespace ll
