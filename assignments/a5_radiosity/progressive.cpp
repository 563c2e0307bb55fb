#include "progressive.h"

#include "metrics/image_metrics.h"

namespace ll::a5 {

ProgressiveRadiosity::ProgressiveRadiosity(const PatchMesh& mesh, const Accelerator& accel, int hemicubeResolution)
    : mesh_(mesh), rows_(mesh, accel, hemicubeResolution), computed_(mesh.patches.size()) {
  for (const Patch& p : mesh.patches) {
    b_.push_back(p.emission);
    emitted_ += static_cast<double>(maxComponent(p.emission) * p.area);
  }
  unshot_ = b_;
}

double ProgressiveRadiosity::unshotFractionLocked() const {
  double left = 0.0;
  for (size_t i = 0; i < unshot_.size(); ++i)
    left += static_cast<double>(maxComponent(unshot_[i]) * mesh_.patches[i].area);
  return emitted_ > 0.0 ? left / emitted_ : 0.0;
}

Rgb ProgressiveRadiosity::ambientLocked() const {
  // The ambient term: the unshot radiosity spread evenly and reflected over and over.
  double area = 0.0;
  Rgb unshotPower(0.0f), rhoMean(0.0f);
  for (size_t i = 0; i < b_.size(); ++i) {
    const Patch& p = mesh_.patches[i];
    area += static_cast<double>(p.area);
    unshotPower += unshot_[i] * p.area;
    rhoMean += p.reflectance * p.area;
  }
  Rgb ambient(0.0f);
  if (area > 0.0) {
    rhoMean /= static_cast<float>(area);
    ambient = unshotPower / static_cast<float>(area) / glm::max(Rgb(1.0f) - rhoMean, Rgb(1e-3f));
  }
  return ambient;
}

std::vector<Rgb> ProgressiveRadiosity::displayed(double* unshotFraction) const {
  const std::lock_guard lock(mutex_);
  const Rgb ambient = ambientLocked();
  std::vector<Rgb> out(b_.size());
  for (size_t i = 0; i < b_.size(); ++i) out[i] = b_[i] + mesh_.patches[i].reflectance * ambient;
  if (unshotFraction) *unshotFraction = unshotFractionLocked();
  return out;
}

double ProgressiveRadiosity::unshotRelMse() const {
  const std::lock_guard lock(mutex_);
  const Rgb ambient = ambientLocked();
  double sum = 0.0, area = 0.0;
  for (size_t i = 0; i < b_.size(); ++i) {
    const Patch& p = mesh_.patches[i];
    const Rgb rest = p.reflectance * ambient / kPi, shown = b_[i] / kPi + rest;  // radiance
    for (int c = 0; c < 3; ++c)
      sum += static_cast<double>(p.area) * static_cast<double>(rest[c]) * static_cast<double>(rest[c]) *
             relMseWeight(static_cast<double>(shown[c]));
    area += 3.0 * static_cast<double>(p.area);
  }
  return area > 0.0 ? sum / area : 0.0;
}

size_t ProgressiveRadiosity::rowsComputed() const {
  const std::lock_guard lock(mutex_);
  size_t n = 0;
  for (const auto& row : computed_) n += !row.empty();
  return n;
}

size_t ProgressiveRadiosity::shots() const {
  const std::lock_guard lock(mutex_);
  return shots_;
}

}  // namespace ll::a5
