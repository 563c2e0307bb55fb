// Technique `radiosity` -- the lecture's radiosity method: the scene as
// small diffuse patches, B = E + rho F B solved once (independent of the
// viewpoint; cached, so moving the camera never recomputes it), then seen
// from the camera: the first surface a camera ray meets shows its
// radiosity interpolated from the patch corners (Gouraud) as radiance B / pi.
//
//   lightlab render SCENE -t radiosity [--set patch_size=0.04]
//     [--set form_factors=hemicube|analytic|montecarlo] [--set hemicube_res=32]
//     [--set solver=gauss-seidel|jacobi|direct|southwell] [--set tolerance=1e-4]
//     [--set show=solution|bounce|bounces --set bounce=K]
//   lightlab radiosity SCENE --json OUT.json     # every patch and the solver's history
#include <memory>
#include <optional>

#include "radiosity_scene.h"
#include "render/technique.h"
#include "scene/camera.h"

namespace ll {

namespace {

class Radiosity final : public PixelTechnique {
 public:
  void prepare(const RenderContext& ctx) override {
    const ScopedTaskLog scope(ctx.taskLog);
    camera_ = renderCamera(ctx.scene, ctx.settings);
    frame_.emplace(camera_);
    gouraud_ = ctx.params.getChoice("interpolate") == "gouraud";
    solved_ = a5::solveScene(ctx.scene, a5::radiositySettings(ctx.params));
    for (const auto& [id, what] : solved_->missingTasks) reportMissingTask(id.c_str(), what.c_str());
  }

 protected:
  const Accelerator& accelerator(const RenderContext&) const override { return solved_->accel(); }

  Rgb renderSample(const RenderContext& ctx, const PixelSample& s, const Tracer& tracer) const override {
    // Pixels of a solution that went through a stub are striped.
    for (const auto& [id, what] : solved_->missingTasks) reportMissingTask(id.c_str(), what.c_str());
    const Ray ray = referenceCameraRay(camera_, *frame_, s.position.x, s.position.y);
    Hit hit;
    if (!tracer.intersect(ray, hit, RayKind::Camera)) return ctx.scene.background;  // (over the patches)
    const a5::Patch& p = solved_->mesh().patches[hit.prim];
    if (glm::dot(p.normal, ray.dir) >= 0.0f) return Rgb(0.0f);  // the back of a patch: not solved
    Rgb b = solved_->shown[hit.prim];
    if (gouraud_) {
      const std::vector<Rgb>& v = solved_->vertexShown;
      b = (1.0f - hit.b1 - hit.b2) * v[p.vertices.x] + hit.b1 * v[p.vertices.y] + hit.b2 * v[p.vertices.z];
    }
    return b / kPi;  // a diffuse surface's radiance
  }

 private:
  Camera camera_;
  std::optional<CameraFrame> frame_;
  bool gouraud_ = true;
  std::shared_ptr<const a5::SolvedRadiosity> solved_;
};

}  // namespace

TechniqueInfo radiosityTechnique() {
  return {
      "radiosity",
      "radiosity: diffuse patches, form factors (hemicube, analytic, Monte Carlo), B = E + rho F B solved once "
      "(direct, Jacobi, Gauss-Seidel, Southwell), shown with interpolated patch radiosities",
      EffectSet{Effect::DirectLighting, Effect::SoftShadows, Effect::HardShadows, Effect::DiffuseInterreflection,
                Effect::Emission},
      3,
      {
          ParamDecl::real("patch_size", 0.04, 0.002, 1.0,
                          "longest patch edge, as a fraction of the scene's bounding-box diagonal"),
          ParamDecl::choice("form_factors", "hemicube", {"hemicube", "analytic", "montecarlo"},
                            "hemicube: ray-cast hemicube per patch; analytic: point-to-polygon contour integral "
                            "times visibility; montecarlo: area-to-area point pairs"),
          ParamDecl::integer("hemicube_res", 32, 4, 512, "hemicube cells along the top face's side"),
          ParamDecl::integer("visibility_samples", 1, 1, 64, "analytic: visibility rays per patch pair"),
          ParamDecl::integer("mc_samples", 16, 1, 4096, "montecarlo: point pairs per patch pair"),
          ParamDecl::choice("solver", "gauss-seidel", {"gauss-seidel", "jacobi", "direct", "southwell"},
                            "direct: dense LU (up to 3000 patches); jacobi/gauss-seidel: sweeps to the tolerance; "
                            "southwell: progressive refinement (shoot the largest unshot power)"),
          ParamDecl::real("tolerance", 1e-4, 1e-9, 0.5, "stop when the relative residual is below this"),
          ParamDecl::integer("max_iterations", 1000, 1, 1000000, "iteration cap (southwell: N shots each)"),
          ParamDecl::choice("show", "solution", {"solution", "bounce", "bounces"},
                            "solution: B; bounce: the K-th term of L = E + KE + K^2E + ... alone; bounces: terms 0..K "
                            "summed"),
          ParamDecl::integer("bounce", 1, 0, 64, "K for show=bounce/bounces"),
          ParamDecl::choice("interpolate", "gouraud", {"gouraud", "flat"},
                            "gouraud: radiosity interpolated from the patch corners; flat: one value per patch"),
          ParamDecl::choice("patch_accelerator", "bvh", {"bvh", "kdtree", "octree", "none"},
                            "the accelerator over the patches for visibility rays and display"),
          ParamDecl::integer("sphere_segments", 24, 6, 256, "tessellation of spheres into patches"),
      },
      []() -> std::unique_ptr<Technique> { return std::make_unique<Radiosity>(); },
  };
}

}  // namespace ll
