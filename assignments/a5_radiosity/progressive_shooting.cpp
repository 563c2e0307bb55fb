// LIGHTLAB_ANSWER_FILE A5.3: the student tree holds this file as object code only.
// Progressive refinement's shooting loop (Cohen et al. 1988; framework code):
// Southwell's iteration, the largest unshot power shooting first, with each
// row of form factors computed when its patch first shoots. It answers A5.3,
// so the student tree holds it as object code only (liblightlab_private.a).
#include "progressive.h"
#include "tasks/framework_answer.h"

namespace ll::a5 {

void ProgressiveRadiosity::advance(size_t shots, double tolerance) {
  LIGHTLAB_ANSWER_GUARD("A5.3", "ll::a5::ProgressiveRadiosity::advance");
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

}  // namespace ll::a5
