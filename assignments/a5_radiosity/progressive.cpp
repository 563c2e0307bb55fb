#include "progressive.h"

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

void ProgressiveRadiosity::advance(size_t shots, double tolerance) {
  const std::lock_guard lock(mutex_);
  if (unshotFractionLocked() <= tolerance) return;  // converged already (e.g. a render after a camera move)
  while (shots_ < shots) {
    // The largest unshot power shoots (Southwell); its row is computed now if it never shot before.
    uint32_t shooter = 0;
    float best = 0.0f;
    for (uint32_t i = 0; i < unshot_.size(); ++i) {
      const float power = maxComponent(unshot_[i]) * mesh_.patches[i].area;
      if (power > best) {
        best = power;
        shooter = i;
      }
    }
    if (!(best > 0.0f)) return;
    if (computed_[shooter].empty()) computed_[shooter] = rows_.row(shooter);
    const Rgb shot = unshot_[shooter];
    const float area = mesh_.patches[shooter].area;
    unshot_[shooter] = Rgb(0.0f);
    for (const FormFactorEntry& e : computed_[shooter]) {
      const Patch& receiver = mesh_.patches[e.j];
      const Rgb received = receiver.reflectance * (e.f * area / receiver.area) * shot;  // rho_j F_ji B_i
      b_[e.j] += received;
      unshot_[e.j] += received;
    }
    ++shots_;
    if ((shots_ & 63u) == 0 && unshotFractionLocked() <= tolerance) return;
  }
}

std::vector<Rgb> ProgressiveRadiosity::displayed(double* unshotFraction) const {
  const std::lock_guard lock(mutex_);
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
  std::vector<Rgb> out(b_.size());
  for (size_t i = 0; i < b_.size(); ++i) out[i] = b_[i] + mesh_.patches[i].reflectance * ambient;
  if (unshotFraction) *unshotFraction = unshotFractionLocked();
  return out;
}

size_t ProgressiveRadiosity::shots() const {
  const std::lock_guard lock(mutex_);
  return shots_;
}

}  // namespace ll::a5
