// Progressive refinement as Cohen et al. (1988) ran it (framework code): the
// Southwell iteration with each form-factor row computed by a hemicube only
// when its patch shoots, so a picture exists after the first few shots (the
// lights) instead of after the whole matrix. Shared by the passes of
// `-t radiosity --set progressive=true` and by later renders of the same
// scene, so moving the camera continues where the solve stands.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "form_factors.h"
#include "patch_mesh.h"

namespace ll::a5 {

class ProgressiveRadiosity {
 public:
  // `mesh` and `accel` must outlive this.
  ProgressiveRadiosity(const PatchMesh& mesh, const Accelerator& accel, int hemicubeResolution);

  // Shoots until `shots` patches have shot in all, or the unshot power is
  // below `tolerance` of the emitted power. Thread-safe.
  void advance(size_t shots, double tolerance);
  // The radiosity to display per patch: B plus the ambient estimate of what
  // is still unshot (rho times it), and the fraction of the emitted power unshot.
  std::vector<Rgb> displayed(double* unshotFraction = nullptr) const;
  size_t shots() const;
  // How much what is still unshot shows: the relMSE (image_metrics.h, on radiance B / pi) of the display
  // without its ambient term against the display, averaged over the patches by area (a picture's pixels
  // weight the patches by how much of the frame they fill, which this does not know).
  double unshotRelMse() const;
  // Hemicube rows computed so far (patches that shot at least once), of mesh.patches.size().
  size_t rowsComputed() const;

 private:
  double unshotFractionLocked() const;
  Rgb ambientLocked() const;

  const PatchMesh& mesh_;
  mutable std::mutex mutex_;
  HemicubeRows rows_;
  std::vector<std::vector<FormFactorEntry>> computed_;  // rows of the patches that shot
  std::vector<Rgb> b_, unshot_;
  size_t shots_ = 0;
  double emitted_ = 0.0;
};

}  // namespace ll::a5
