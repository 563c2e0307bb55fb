// Technique `blinn-phong` -- the lecture's local shading model on a software
// rasterizer (assignment 1), the CPU twin of `blinn-phong-gl`:
//   L = Le + ka*Ia + sum over lights [ kd*(I/r^2)*max(0, n.l) + ks*(I/r^2)*max(0, n.h)^p ]
// Point lights as declared; directional lights without 1/r^2; each area light
// as an n x n grid of point lights (n = round(sqrt(light_samples))) of
// intensity Le * (A / n^2) * max(0, n_light . -l) / pi. Two-sided: n is turned
// towards the eye. No shadows. Shading frequency: flat (the triangle's normal,
// lit per sample), gouraud (D and S lit per vertex and interpolated, kd and
// its texture per sample), phong (interpolated normal lit per sample).
//
//   lightlab render SCENE -t blinn-phong [--set shading=flat|gouraud|phong]
//     [--set samples=1|4|16] [--set filter=nearest|bilinear|trilinear]
//     [--set light_samples=16] [--set sphere_segments=48]
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "a1_tasks.h"
#include "rasterizer.h"
#include "render/raster_scene.h"
#include "render/technique.h"

namespace ll {

namespace {

enum class Shading { Flat, Gouraud, Phong };

class BlinnPhongShader final : public a1::Shader {
 public:
  BlinnPhongShader(const Scene& scene, const RasterMesh& mesh, const std::vector<RasterLight>& lights,
                   const std::vector<uint32_t>& objectMaterial, const std::vector<a1::MipChain>& mips,
                   const Mat4& viewProjection, Vec3 eye, Shading shading, a1::TextureFilter filter)
      : scene_(scene),
        mesh_(mesh),
        lights_(lights),
        objectMaterial_(objectMaterial),
        mips_(mips),
        viewProjection_(viewProjection),
        eye_(eye),
        shading_(shading),
        filter_(filter) {}

  Vec4 vertex(int index, int object, a1::Varyings& out) const override {
    const RasterVertex& v = mesh_.vertices[static_cast<size_t>(index)];
    out.position = v.position;
    out.normal = v.normal;
    out.uv = v.uv;
    if (shading_ == Shading::Gouraud) {
      const a1::LightTerms sums = lightSums(v.position, glm::normalize(v.normal), material(object).shininess);
      out.diffuse = sums.diffuse;
      out.specular = sums.specular;
    }
    return viewProjection_ * Vec4(v.position, 1.0f);
  }

  Rgb fragment(const a1::Fragment& f) const override {
    const Material& m = material(f.object);
    a1::LightTerms sums{f.in.diffuse, f.in.specular};
    if (shading_ == Shading::Flat) sums = lightSums(f.in.position, f.faceNormal, m.shininess);
    if (shading_ == Shading::Phong) sums = lightSums(f.in.position, glm::normalize(f.in.normal), m.shininess);
    Rgb kd = m.kd;
    if (m.texture.kind == Texture::Kind::Checker) kd = m.texture.eval(f.in.uv);
    if (m.texture.kind == Texture::Kind::Image) {
      const a1::MipChain& chain = mips_[objectMaterial_[static_cast<size_t>(f.object)]];
      const Vec2 size(static_cast<float>(chain.level(0).width()), static_cast<float>(chain.level(0).height()));
      // Level of detail: log2 of the texels one sample step covers (the larger of x and y).
      const float rho = std::max(glm::length(f.uvDx * size), glm::length(f.uvDy * size));
      kd *= a1::sampleTexture(chain, f.in.uv, std::log2(rho), filter_);
    }
    return m.emission + m.ka * scene_.ambient + kd * sums.diffuse + m.ks * sums.specular;
  }

 private:
  const Material& material(int object) const {
    return scene_.materials[objectMaterial_[static_cast<size_t>(object)]];
  }

  // The lights' diffuse and specular sums D, S at a world point with unit normal n (either side).
  a1::LightTerms lightSums(Vec3 position, Vec3 n, float shininess) const {
    const Vec3 v = glm::normalize(eye_ - position);
    if (glm::dot(n, v) < 0.0f) n = -n;  // two-sided, as the ray tracers shade
    a1::LightTerms sum;
    for (const RasterLight& light : lights_) {
      Vec3 l;
      Rgb irradiance = light.intensity;
      if (light.kind == RasterLight::Kind::Directional) {
        l = light.position;
      } else {
        const Vec3 d = light.position - position;
        const float r2 = std::max(glm::dot(d, d), 1e-12f);
        l = d / std::sqrt(r2);
        irradiance /= r2;
        if (light.kind == RasterLight::Kind::AreaSample)
          irradiance *= std::max(0.0f, glm::dot(light.normal, -l)) / kPi;
      }
      const a1::LightTerms t = a1::blinnPhong(n, v, l, irradiance, shininess);
      sum.diffuse += t.diffuse;
      sum.specular += t.specular;
    }
    return sum;
  }

  const Scene& scene_;
  const RasterMesh& mesh_;
  const std::vector<RasterLight>& lights_;
  const std::vector<uint32_t>& objectMaterial_;
  const std::vector<a1::MipChain>& mips_;
  Mat4 viewProjection_;
  Vec3 eye_;
  Shading shading_;
  a1::TextureFilter filter_;
};

class BlinnPhongRaster final : public Technique {
 public:
  int passCount(const RenderContext&) const override { return 1; }

  void prepare(const RenderContext& ctx) override {
    const ParamSet& p = ctx.params;
    mesh_ = buildRasterMesh(ctx.scene, p.getInt("sphere_segments"));
    lights_ = rasterLights(ctx.scene, p.getInt("light_samples"));
    objectMaterial_.clear();
    for (const SceneObject& o : ctx.scene.objects) objectMaterial_.push_back(o.material);
    mips_.assign(ctx.scene.materials.size(), a1::MipChain());
    for (size_t i = 0; i < ctx.scene.materials.size(); ++i) {
      const Texture& t = ctx.scene.materials[i].texture;
      if (t.kind == Texture::Kind::Image) mips_[i] = a1::MipChain(*t.image);
    }
  }

  void renderPass(const RenderContext& ctx, int pass, FrameBuffer& fb, WorkCounters& counters,
                  const std::atomic<bool>& cancel) override {
    (void)pass;
    const ParamSet& p = ctx.params;
    const Camera camera = renderCamera(ctx.scene, ctx.settings);
    // Depth range fitted to the scene's bounds (as blinn-phong-gl).
    const DepthRange depth = rasterDepthRange(ctx.scene, camera);
    Mat4 viewProjection(1.0f);
    {
      const ScopedTaskLog log(ctx.taskLog);
      viewProjection = a1::viewProjection(camera, depth.near, depth.far);
    }
    const std::string& shadingName = p.getChoice("shading");
    const Shading shading = shadingName == "flat"      ? Shading::Flat
                            : shadingName == "gouraud" ? Shading::Gouraud
                                                       : Shading::Phong;
    const std::string& filterName = p.getChoice("filter");
    const a1::TextureFilter filter = filterName == "nearest"    ? a1::TextureFilter::Nearest
                                     : filterName == "bilinear" ? a1::TextureFilter::Bilinear
                                                                : a1::TextureFilter::Trilinear;
    const std::string& samples = p.getChoice("samples");

    BlinnPhongShader shader(ctx.scene, mesh_, lights_, objectMaterial_, mips_, viewProjection, camera.eye, shading,
                            filter);
    a1::RasterSettings settings;
    settings.width = fb.width();
    settings.height = fb.height();
    settings.scale = samples == "16" ? 4 : samples == "4" ? 2 : 1;
    settings.background = ctx.scene.background;
    settings.taskLog = ctx.taskLog;
    // One draw call per object (the vertex stage needs the object's material for Gouraud).
    std::vector<a1::DrawCall> draws;
    for (size_t o = 0; o < mesh_.ranges.size(); ++o)
      draws.push_back({mesh_.ranges[o].first, mesh_.ranges[o].second, static_cast<int>(o)});
    counters.nonFinite += a1::rasterize(workspace_, shader, draws, settings, fb, cancel);
  }

 private:
  RasterMesh mesh_;
  std::vector<RasterLight> lights_;
  std::vector<uint32_t> objectMaterial_;
  std::vector<a1::MipChain> mips_;  // per material; empty unless it has an image texture
  a1::RasterWorkspace workspace_;   // frame-to-frame buffers
};

}  // namespace

TechniqueInfo blinnPhongTechnique() {
  return {"blinn-phong",
          "software rasterizer (assignment 1): the lecture's Blinn-Phong, flat/Gouraud/Phong, supersampled, "
          "texture filtering; no shadows",
          EffectSet{Effect::DirectLighting, Effect::GlossyHighlights, Effect::Textures, Effect::Emission},
          0,
          {ParamDecl::choice("shading", "phong", {"flat", "gouraud", "phong"},
                             "flat: the triangle's normal, lit per sample; gouraud: lit per vertex and "
                             "interpolated; phong: interpolated normals, lit per sample"),
           ParamDecl::choice("samples", "1", {"1", "4", "16"}, "supersamples per pixel (ordered grid 1x1, 2x2, 4x4)"),
           ParamDecl::choice("filter", "trilinear", {"nearest", "bilinear", "trilinear"},
                             "texture filtering (trilinear uses mipmaps)"),
           ParamDecl::integer("light_samples", 16, 1, 64,
                              "point lights per area light (rounded to a square grid)"),
           ParamDecl::integer("sphere_segments", 48, 8, 256, "tessellation of spheres around the equator")},
          []() -> std::unique_ptr<Technique> { return std::make_unique<BlinnPhongRaster>(); }};
}

}  // namespace ll
