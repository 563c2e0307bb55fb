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
//   lightlab render SCENE -t radiosity-raster     # the same solution through A1's rasterizer
#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>

#include "core/timer.h"
#include "radiosity_scene.h"
#include "rasterizer.h"
#include "render/light_path_class.h"
#include "render/light_path_probe.h"
#include "render/raster_scene.h"
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
    classCorners_.clear();
    skipped_.reset();
    measured_ = ctx.params.getChoice("effects") == "measured";
    effectsTolerance_ = ctx.params.getFloat("effects_tolerance");
    if (measured_) settings_.progressive = true;  // what is not shot is not computed
    if (settings_.progressive) {
      progressive_ = a5::progressiveScene(ctx.scene, settings_);
      shootingSeconds_ = 0.0;
      patches_ = progressive_.patches;
      solved_.reset();
      return;
    }
    solved_ = a5::solveScene(ctx.scene, settings_);
    patches_ = solved_->patches;
    shown_ = solved_->shown;
    corners_ = solved_->vertexShown;
    solved_->replayTasks();
    if (ctx.settings.lightPaths) splitByBounce();
  }

  // The picture split by bounce, as light-path classes: E is what path calls emission (L E), K E its
  // direct lighting (L D E), K^2 E + K^3 E + ... its diffuse interreflection (L D D+ E). Needs F (not
  // hierarchical, not progressive).
  bool splitsLightPaths() const override { return !classCorners_.empty(); }

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
    if (measured_)
      shootWhileItShows(shots, last);
    else
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
    if (!tracer.intersect(ray, hit, RayKind::Camera))  // (over the patches)
      return ctx.scene.environment.radiance(glm::normalize(ray.dir));
    const a5::PatchMesh& mesh = patches_->mesh;
    const uint32_t patch = mesh.primPatch[hit.prim];  // (a quad patch is two triangles)
    if (glm::dot(mesh.patches[patch].normal, ray.dir) >= 0.0f) return Rgb(0.0f);  // the back of a patch: not solved
    // A per-patch radiosity at the hit: from the patch corners (Gouraud) or the patch's own value.
    const glm::uvec3& t = mesh.geometry.triangles[hit.prim];
    const auto at = [&](const std::vector<Rgb>& perPatch, const std::vector<Rgb>& perCorner) {
      return gouraud_ ? (1.0f - hit.b1 - hit.b2) * perCorner[t.x] + hit.b1 * perCorner[t.y] + hit.b2 * perCorner[t.z]
                      : perPatch[patch];
    };
    if (s.lightPaths && !classCorners_.empty())
      for (size_t k = 0; k < kSplit.size(); ++k)
        s.lightPaths[static_cast<size_t>(kSplit[k])] = at(classPatches_[k], classCorners_[k]) / kPi;
    return at(shown_, corners_) / kPi;  // a diffuse surface's radiance
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

  // --set effects=measured: shoots (Southwell, rows computed per shot) up to `shots`, but only while the light
  // still unshot shows, i.e. while the display without its ambient term differs from the display by more
  // than effects_tolerance (relMSE, averaged over the patches by area). Patches whose unshot light does not
  // show never shoot, and their hemicube rows are never computed.
  void shootWhileItShows(size_t shots, bool last) {
    a5::ProgressiveRadiosity& state = *progressive_.state;
    const Timer timer;
    while (state.unshotRelMse() > effectsTolerance_ && state.shots() < shots) {
      const size_t before = state.shots();
      state.advance(std::min(shots, before + std::max<size_t>(8, before / 8)), settings_.solver.tolerance);
      if (state.shots() == before) break;  // converged to the solver's tolerance, or nothing left to shoot
    }
    shootingSeconds_ += timer.seconds();
    if (!last) return;
    SkippedWork w;
    w.tolerance = effectsTolerance_;
    w.errorAdded = w.errorAddedHigh = state.unshotRelMse();  // an estimate: the ambient term's, not a bound
    const size_t rows = state.rowsComputed(), patches = patches_->mesh.patches.size();
    char text[256];
    std::snprintf(text, sizeof text, "the shots of %zu of %zu patches, whose unshot light does not show (the "
                  "ambient term stands for it)", patches - std::min(rows, patches), patches);
    if (rows == 0 && w.errorAdded == 0.0) {
      w.skipped = "nothing: no patch emits light (radiosity's light comes from emissive surfaces only)";
    } else {
      w.skipped = text;
      // The rows not computed would have cost what the computed ones did on average (rows dominate a shot).
      const size_t notComputed = patches - std::min(rows, patches);
      const double savedSeconds =
          rows > 0 ? shootingSeconds_ / static_cast<double>(rows) * static_cast<double>(notComputed) : 0.0;
      std::snprintf(text, sizeof text,
                    "%zu of %zu hemicube rows computed (%.0f %% of the form factors not: about %.2g s, estimated "
                    "from the %.2g s the computed ones took)",
                    rows, patches, patches ? 100.0 * static_cast<double>(notComputed) / static_cast<double>(patches) : 0.0,
                    savedSeconds, shootingSeconds_);
      w.saved = text;
    }
    skipped_ = w;
  }

  std::optional<SkippedWork> skippedWork() const override { return skipped_; }

  bool measured_ = false;
  double effectsTolerance_ = 1e-3;
  double shootingSeconds_ = 0.0;  // effects=measured: time spent shooting in this solve's passes
  std::optional<SkippedWork> skipped_;

  // The classes bounce 0, 1 and 2+ fall in; per class, the shown radiosity's part per patch and per vertex.
  static constexpr std::array<LightPathClass, 3> kSplit{LightPathClass::Emission, LightPathClass::DirectLighting,
                                                        LightPathClass::DiffuseInterreflection};
  std::array<std::vector<Rgb>, 3> classPatches_;
  std::vector<std::vector<Rgb>> classCorners_;

  void splitByBounce() {
    if (solved_->f().size() == 0) return;
    const a5::RadiositySystem system = solved_->system();
    // Which terms of E + KE + K^2E + ... the display shows (show=bounce: term k alone; bounces: 0..k).
    const bool single = settings_.show == a5::RadiositySettings::Show::Bounce;
    const int last = settings_.show == a5::RadiositySettings::Show::Solution ? 1 << 30 : settings_.bounce;
    const int first = single ? settings_.bounce : 0;
    for (size_t k = 0; k < 3; ++k) classPatches_[k].assign(shown_.size(), Rgb(0.0f));
    std::vector<Rgb> rest = shown_;  // what bounces 0 and 1 leave: bounces 2+ (and the ambient term)
    for (int k = 0; k <= 1; ++k) {
      if (k < first || k > last) continue;
      const std::vector<Rgb> term = a5::bounce(system, k);
      for (size_t i = 0; i < rest.size(); ++i) {
        classPatches_[static_cast<size_t>(k)][i] = isFinite(term[i]) ? term[i] : Rgb(0.0f);
        rest[i] -= classPatches_[static_cast<size_t>(k)][i];
      }
    }
    if (last >= 2) classPatches_[2] = rest;
    for (const std::vector<Rgb>& c : classPatches_) classCorners_.push_back(cornerValues(patches_->mesh, c));
  }
};

// The parameters of the solve, shared by both displays.
std::vector<ParamDecl> radiosityParams() {
  return {
      ParamDecl::real("patch_size", 0.04, 0.002, 1.0,
                      "longest patch edge, as a fraction of the scene's bounding-box diagonal"),
      ParamDecl::boolean("quad_patches", true,
                         "flat quads (walls, box faces) become grids of quad patches; false: triangles everywhere"),
      ParamDecl::boolean("discontinuity_meshing", true,
                         "cut flat surfaces along the outlines of what lies on them (the lamp on the ceiling, "
                         "the blocks on the floor) before meshing, so no patch straddles the jump"),
      ParamDecl::integer("adaptive_passes", 0, 0, 8,
                         "adaptive refinement: rounds of solving and splitting patches whose radiosity differs "
                         "from a neighbour's by more than adaptive_threshold (on triangles: quad patches become "
                         "two each in the first round)"),
      ParamDecl::real("adaptive_threshold", 0.25, 0.01, 10.0,
                      "relative radiosity difference between neighbouring patches that splits them"),
      ParamDecl::choice("form_factors", "hemicube", {"hemicube", "analytic", "montecarlo"},
                        "hemicube: ray-cast hemicube per patch; analytic: point-to-polygon contour integral "
                        "times visibility; montecarlo: area-to-area point pairs"),
      ParamDecl::integer("hemicube_res", 32, 4, 512, "hemicube cells along the top face's side"),
      ParamDecl::integer("visibility_samples", 1, 1, 64, "analytic: visibility rays per patch pair"),
      ParamDecl::integer("mc_samples", 16, 1, 4096, "montecarlo: point pairs per patch pair"),
      ParamDecl::choice("solver", "gauss-seidel", {"gauss-seidel", "jacobi", "direct", "southwell", "hierarchical"},
                        "direct: dense LU (up to 3000 patches); jacobi/gauss-seidel: sweeps to the tolerance; "
                        "southwell: progressive refinement (shoot the largest unshot power); hierarchical: "
                        "Hanrahan et al. 1991, elements and links refined where they carry much power "
                        "(patch_size, form_factors and show do not apply)"),
      ParamDecl::real("link_epsilon", 1e-4, 1e-8, 1e-1,
                      "hierarchical: a link is refined while it carries more than this fraction of the emitted "
                      "power (smaller: more elements, more accurate, slower)"),
      ParamDecl::real("tolerance", 1e-4, 1e-9, 0.5, "stop when the relative residual is below this"),
      ParamDecl::integer("max_iterations", 1000, 1, 1000000, "iteration cap (southwell: N shots each)"),
      ParamDecl::choice("show", "solution", {"solution", "bounce", "bounces"},
                        "solution: B; bounce: the K-th term of L = E + KE + K^2E + ... alone; bounces: terms 0..K "
                        "summed"),
      ParamDecl::integer("bounce", 1, 0, 64, "K for show=bounce/bounces"),
      ParamDecl::choice("interpolate", "gouraud", {"gouraud", "flat"},
                        "gouraud: radiosity interpolated from the patch corners; flat: one value per patch"),
      // Embree where there is one: the hemicubes' rays are most of the solve's time (Cornell box, 8349
      // patches, 2 threads: 3.4 s of form factors against 5.5 s with the BVH of assignment 4).
      ParamDecl::choice("patch_accelerator",
#ifdef LIGHTLAB_HAVE_EMBREE
                        "embree",
#else
                        "bvh",
#endif
                        {"bvh", "kdtree", "octree", "none"
#ifdef LIGHTLAB_HAVE_EMBREE
                         ,
                         "embree"
#endif
                        },
                        "the accelerator over the patches for visibility rays and display (embree, the default "
                        "where built with it: the framework's, independent of assignment 4; bvh, kdtree, octree: "
                        "assignment 4's)"),
      ParamDecl::integer("sphere_segments", 24, 6, 256, "tessellation of spheres into patches"),
      ParamDecl::boolean("progressive", false,
                         "progressive refinement (Cohen 1988): Southwell shooting with hemicube rows computed "
                         "per shot; every pass shoots twice as many patches and redraws, the last to the "
                         "tolerance (form_factors, solver and show do not apply)"),
  };
}

// The display through the rasterizer of assignment 1: the patches as
// triangles whose corners carry their radiosity, interpolated
// perspective-correctly; the same picture as `radiosity` up to the
// rasterizer's sampling. Runs the A1 pipeline (edge functions, z-buffer).
class RadiosityRasterShader final : public a1::Shader {
 public:
  RadiosityRasterShader(const a5::PatchMesh& mesh, const std::vector<Rgb>& shown, const std::vector<Rgb>& corners,
                        bool gouraud, const Mat4& viewProjection, Vec3 eye)
      : mesh_(mesh), shown_(shown), corners_(corners), gouraud_(gouraud), viewProjection_(viewProjection), eye_(eye) {}
  // Vertex k of triangle k / 3 (a quad patch is two).
  Vec4 vertex(int index, int, a1::Varyings& out) const override {
    const auto triangle = static_cast<uint32_t>(index / 3);
    const uint32_t v = mesh_.geometry.triangles[triangle][index % 3];
    out.position = mesh_.positions[v];
    out.diffuse = gouraud_ ? corners_[v] : shown_[mesh_.primPatch[triangle]];
    return viewProjection_ * Vec4(out.position, 1.0f);
  }
  Rgb fragment(const a1::Fragment& f) const override {
    if (glm::dot(f.faceNormal, eye_ - f.in.position) <= 0.0f) return Rgb(0.0f);  // the back of a patch
    return f.in.diffuse / kPi;
  }

 private:
  const a5::PatchMesh& mesh_;
  const std::vector<Rgb>& shown_;
  const std::vector<Rgb>& corners_;
  bool gouraud_;
  Mat4 viewProjection_;
  Vec3 eye_;
};

class RadiosityRaster final : public Technique {
 public:
  int passCount(const RenderContext&) const override { return 1; }
  void prepare(const RenderContext& ctx) override {
    const ScopedTaskLog scope(ctx.taskLog);
    settings_ = a5::radiositySettings(ctx.params);
    settings_.progressive = false;
    solved_ = a5::solveScene(ctx.scene, settings_);
    solved_->replayTasks();
  }
  void renderPass(const RenderContext& ctx, int, FrameBuffer& fb, WorkCounters& counters,
                  const std::atomic<bool>& cancel) override {
    const Camera camera = renderCamera(ctx.scene, ctx.settings);
    const DepthRange depth = rasterDepthRange(ctx.scene, camera);
    const Mat4 viewProjection = glm::perspective(radians(camera.fovYDeg), camera.aspect(), depth.near, depth.far) *
                                glm::lookAt(camera.eye, camera.target, camera.up);
    const RadiosityRasterShader shader(solved_->mesh(), solved_->shown, solved_->vertexShown,
                                       ctx.params.getChoice("interpolate") == "gouraud", viewProjection, camera.eye);
    a1::RasterSettings s;
    s.width = fb.width();
    s.height = fb.height();
    const std::string& samples = ctx.params.getChoice("samples");
    s.scale = samples == "16" ? 4 : samples == "4" ? 2 : 1;
    s.background = ctx.scene.background;
    s.taskLog = ctx.taskLog;
    const int vertices = static_cast<int>(3 * solved_->mesh().geometry.triangles.size());
    counters.nonFinite += a1::rasterize(workspace_, shader, {a1::DrawCall{0, vertices, 0}}, s, fb, cancel);
  }

 private:
  a5::RadiositySettings settings_;
  std::shared_ptr<const a5::SolvedRadiosity> solved_;
  a1::RasterWorkspace workspace_;
};

}  // namespace

TechniqueInfo radiosityTechnique() {
  TechniqueInfo t{
      "radiosity",
      "radiosity: diffuse patches, form factors (hemicube, analytic, Monte Carlo), B = E + rho F B solved once "
      "(direct, Jacobi, Gauss-Seidel, Southwell, progressive), shown with interpolated patch radiosities by ray casting; "
      "light from emissive surfaces only (point and directional lights light nothing)",
      EffectSet{Effect::DirectLighting, Effect::SoftShadows, Effect::HardShadows, Effect::DiffuseInterreflection,
                Effect::Emission},
      3,
      withEffectsParams(radiosityParams(),
                        "progressive refinement that stops shooting once the light still unshot (its ambient "
                        "term) changes the picture by less than effects_tolerance, so patches whose light does "
                        "not show never shoot"),
      []() -> std::unique_ptr<Technique> { return std::make_unique<Radiosity>(); },
  };
  t.pointLights = false;  // light enters as the emission E of patches
  return t;
}

TechniqueInfo radiosityRasterTechnique() {
  std::vector<ParamDecl> params = radiosityParams();
  params.push_back(ParamDecl::choice("samples", "4", {"1", "4", "16"}, "supersamples per pixel of the rasterizer"));
  TechniqueInfo t{
      "radiosity-raster",
      "radiosity's solution drawn by the software rasterizer of assignment 1 (the same solve as `radiosity`, "
      "another display; progressive does not apply)",
      EffectSet{Effect::DirectLighting, Effect::SoftShadows, Effect::HardShadows, Effect::DiffuseInterreflection,
                Effect::Emission},
      3,
      params,
      []() -> std::unique_ptr<Technique> { return std::make_unique<RadiosityRaster>(); },
  };
  t.pointLights = false;
  return t;
}

}  // namespace ll
