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
#include <algorithm>
#include <memory>
#include <optional>

#include "radiosity_scene.h"
#include "render/technique.h"
#include "scene/camera.h"

namespace ll {

namespace {

// Corner radiosities: the area-weighted mean of the patches around each mesh vertex.
std::vector<Rgb> cornerValues(const a5::PatchMesh& mesh, const std::vector<Rgb>& perPatch) {
  std::vector<Rgb> out(mesh.positions.size(), Rgb(0.0f));
  for (size_t v = 0; v < out.size(); ++v) {
    float area = 0.0f;
    for (uint32_t p : mesh.vertexPatches[v]) {
      out[v] += perPatch[p] * mesh.patches[p].area;
      area += mesh.patches[p].area;
    }
    if (area > 0.0f) out[v] /= area;
  }
  return out;
}

class Radiosity final : public PixelTechnique {
 public:
  void prepare(const RenderContext& ctx) override {
    const ScopedTaskLog scope(ctx.taskLog);
    camera_ = renderCamera(ctx.scene, ctx.settings);
    frame_.emplace(camera_);
    gouraud_ = ctx.params.getChoice("interpolate") == "gouraud";
    settings_ = a5::radiositySettings(ctx.params);
    if (settings_.progressive) {
      progressive_ = a5::progressiveScene(ctx.scene, settings_);
      patches_ = progressive_.patches;
      solved_.reset();
      return;
    }
    solved_ = a5::solveScene(ctx.scene, settings_);
    patches_ = solved_->patches;
    shown_ = solved_->shown;
    corners_ = solved_->vertexShown;
    for (const auto& [id, what] : solved_->missingTasks) reportMissingTask(id.c_str(), what.c_str());
  }

 protected:
  const Accelerator& accelerator(const RenderContext&) const override { return *patches_->accel; }

  // Progressive: every pass is one whole picture of the solve as it stands.
  int samplesPerPixel(const RenderContext& ctx) const override {
    return settings_.progressive ? 1 : passCount(ctx);
  }

  void beginPass(const RenderContext& ctx, int pass, FrameBuffer& fb) override {
    if (!settings_.progressive) return;
    // Pass k: until 32 * 2^k patches have shot; the last pass to the tolerance.
    const bool last = pass + 1 >= passCount(ctx);
    const size_t shots = last ? ~size_t{0} : size_t{32} << std::min(pass, 40);
    progressive_.state->advance(shots, settings_.solver.tolerance);
    shown_ = progressive_.state->displayed();
    corners_ = cornerValues(patches_->mesh, shown_);
    fb.clearSamples();
  }

  Rgb renderSample(const RenderContext& ctx, const PixelSample& s, const Tracer& tracer) const override {
    // Pixels of a solution that went through a stub are striped.
    if (solved_)
      for (const auto& [id, what] : solved_->missingTasks) reportMissingTask(id.c_str(), what.c_str());
    const Ray ray = referenceCameraRay(camera_, *frame_, s.position.x, s.position.y);
    Hit hit;
    if (!tracer.intersect(ray, hit, RayKind::Camera)) return ctx.scene.background;  // (over the patches)
    const a5::Patch& p = patches_->mesh.patches[hit.prim];
    if (glm::dot(p.normal, ray.dir) >= 0.0f) return Rgb(0.0f);  // the back of a patch: not solved
    Rgb b = shown_[hit.prim];
    if (gouraud_)
      b = (1.0f - hit.b1 - hit.b2) * corners_[p.vertices.x] + hit.b1 * corners_[p.vertices.y] +
          hit.b2 * corners_[p.vertices.z];
    return b / kPi;  // a diffuse surface's radiance
  }

 private:
  Camera camera_;
  std::optional<CameraFrame> frame_;
  bool gouraud_ = true;
  a5::RadiositySettings settings_;
  std::shared_ptr<const a5::SolvedRadiosity> solved_;  // batch solve
  a5::ProgressiveScene progressive_;                   // or progressive refinement
  std::shared_ptr<const a5::PatchScene> patches_;
  std::vector<Rgb> shown_, corners_;  // per patch and per mesh vertex: the radiosity shown
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
          ParamDecl::boolean("progressive", false,
                             "progressive refinement (Cohen 1988): Southwell shooting with hemicube rows computed "
                             "per shot; every pass shoots twice as many patches and redraws, the last to the "
                             "tolerance (form_factors, solver and show do not apply)"),
      },
      []() -> std::unique_ptr<Technique> { return std::make_unique<Radiosity>(); },
  };
}

}  // namespace ll
