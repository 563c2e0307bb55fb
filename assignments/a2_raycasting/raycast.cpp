// Technique `raycast` -- ray casting (Appel 1968): one camera ray per pixel
// sample, the lecture's Blinn-Phong model at the first hit, and a shadow ray
// to every point light and to every sample of every area light.
//
//   lightlab render SCENE -t raycast [--spp N] [--set light_samples=16]
//                   [--set intersection=auto|student|framework] [--set shadows=filtered|opaque]
//
// Shadow rays are filtered as Whitted's are (render/shadow_transmittance.h):
// glass in the way tints the light and absorbs it along its path inside;
// the camera is in air (ray casting does not refract).
// Area lights (emissive geometry) are sampled as light_samples point lights
// of intensity I = Le * (A / N) * cos(theta_light) / pi each, which makes the
// diffuse term the physically right (kd / pi) * E. Framework code: students
// write the functions in a2_tasks.h, which this file calls.
#include <cmath>
#include <memory>

#include "a2_tasks.h"
#include "render/ray_offset.h"
#include "render/shadow_transmittance.h"
#include "render/technique.h"
#include "student_intersector.h"

namespace ll {

namespace {

class Raycast final : public PixelTechnique {
 public:
  void prepare(const RenderContext& ctx) override {
    camera_ = renderCamera(ctx.scene, ctx.settings);
    lightSamples_ = ctx.params.getInt("light_samples");
    // Only a scene with transmissive surfaces has anything to filter: elsewhere the cheaper any-hit query.
    filtered_ = ctx.params.getChoice("shadows") == "filtered" && ctx.scene.hasTransmission;
    student_.reset();
    // auto: your tests when there is no accelerator (-a none, the default), else the accelerator's.
    const std::string& choice = ctx.params.getChoice("intersection");
    if (choice == "student" || (choice == "auto" && ctx.accel.testsEveryPrimitive())) {
      student_ = a2::makeStudentIntersector();
      student_->build(ctx.scene.geometry);
    }
  }

  // `lightlab trace --pixel X Y -t raycast`: the camera ray (your A2.1, hit by your A2.2/A2.3 where the
  // render uses them) and one shadow ray per light sample, each with the Blinn-Phong term it adds (your
  // A2.4, A2.5); the camera ray's own share is emission and ambient. The shares add up to the pixel.
  std::optional<RayTree> rayTree(const RenderContext& ctx, Vec2 position) const override {
    WorkCounters counters;
    const Tracer tracer(ctx.scene, accelerator(ctx), counters);
    // The random stream of the pixel's first sample, as the render draws it.
    const auto pixel = static_cast<uint64_t>(std::floor(position.y)) * static_cast<uint64_t>(camera_.width) +
                       static_cast<uint64_t>(std::floor(position.x));
    Rng rng = Rng::forPixel(ctx.settings.seed, pixel, 0);
    PixelSample s;
    s.x = static_cast<int>(std::floor(position.x));
    s.y = static_cast<int>(std::floor(position.y));
    s.position = position;
    s.rng = &rng;
    RayTree tree;
    tree.pixel = sample(ctx, s, tracer, &tree);
    return tree;
  }

 protected:
  const Accelerator& accelerator(const RenderContext& ctx) const override {
    return student_ ? *student_ : ctx.accel;
  }

  Rgb renderSample(const RenderContext& ctx, const PixelSample& s, const Tracer& tracer) const override {
    return sample(ctx, s, tracer, nullptr);
  }

 private:
  // The sample's radiance; with `tree`, its rays recorded there too.
  Rgb sample(const RenderContext& ctx, const PixelSample& s, const Tracer& tracer, RayTree* tree) const {
    const Scene& scene = ctx.scene;
    Ray ray = a2::cameraRay(camera_, s.position.x, s.position.y);
    Hit hit;
    const bool found = tracer.intersect(ray, hit, RayKind::Camera);
    if (tree) {
      RayTreeNode camera;
      camera.origin = ray.origin;
      camera.direction = glm::normalize(ray.dir);
      camera.intersected = true;
      tree->nodes.push_back(camera);
    }
    if (!found) {
      const Rgb background = scene.environment.radiance(glm::normalize(ray.dir));
      if (tree) tree->nodes[0].radiance = background;
      return background;
    }
    SurfacePoint sp = scene.surfacePoint(ray, hit);
    const Material& m = *sp.material;
    const Vec3 v = -glm::normalize(ray.dir);
    const bool frontFace = glm::dot(sp.geometricNormal, v) > 0.0f;
    // Surfaces are two-sided for shading: turn both normals to the viewer.
    sp.geometricNormal = faceTowards(sp.geometricNormal, v);
    sp.shadingNormal = faceTowards(sp.shadingNormal, v);

    Rgb radiance = frontFace ? m.emission : Rgb(0.0f);  // emitters emit on their front side
    radiance += m.ka * scene.ambient;                    // the lecture's ka * Ia
    const a2::ShadingInput surface{sp.shadingNormal, v, m.diffuse(sp.uv), m.ks, m.shininess};
    if (tree) {
      RayTreeNode& camera = tree->nodes[0];
      camera.hit = true;
      camera.t = hit.t;
      camera.position = sp.position;
      camera.normal = sp.shadingNormal;
      camera.object = scene.objects[sp.object].name;
      camera.material = m.name;
      camera.entering = frontFace;
      camera.local = camera.contribution = radiance;  // emission and ambient; the lights' terms follow
    }

    for (const Light& light : scene.lights) {
      a2::LightInput in{};
      in.intensity = light.intensity;
      if (light.type == Light::Type::Point) {
        const Vec3 d = light.position - sp.position;
        in.distance = glm::length(d);
        in.l = d / in.distance;
      } else {
        in.distance = kInfinity;
        in.l = -light.direction;
      }
      radiance += shade(scene, tracer, sp, surface, in, light.canBeOccluded, tree);
    }

    for (const AreaLight& light : scene.areaLights) {
      for (int k = 0; k < lightSamples_; ++k) {
        const LightPoint lp = scene.sampleAreaLight(light, stratifiedSample(k, lightSamples_, *s.rng));
        const Vec3 target = offsetRayOrigin(lp.position, faceTowards(lp.normal, sp.position - lp.position));
        const Vec3 d = target - sp.position;
        a2::LightInput in{};
        in.distance = glm::length(d);
        if (!(in.distance > 0.0f)) continue;
        in.l = d / in.distance;
        const float cosLight = glm::dot(lp.normal, -in.l);
        if (cosLight <= 0.0f) continue;  // behind the emitting side
        in.intensity = lp.emission * (light.area / static_cast<float>(lightSamples_)) * cosLight / kPi;
        radiance += shade(scene, tracer, sp, surface, in, light.canBeOccluded, tree);
      }
    }
    if (tree) tree->nodes[0].radiance = radiance;
    return radiance;
  }

  // One light's Blinn-Phong term, if the light is in front of the surface and visible; with `tree`, its
  // shadow ray recorded there with the term as its contribution (a light without one: a shadow-free ray).
  Rgb shade(const Scene& scene, const Tracer& tracer, const SurfacePoint& sp, const a2::ShadingInput& surface,
            const a2::LightInput& light, bool castShadow, RayTree* tree) const {
    if (glm::dot(sp.geometricNormal, light.l) <= 0.0f) return Rgb(0.0f);  // the surface itself blocks it
    Rgb through(1.0f);  // how much of the light arrives
    Ray shadow;
    if (castShadow) {
      shadow = a2::shadowRay(sp, light.l, light.distance);
      through = !filtered_ ? (tracer.occluded(shadow) ? Rgb(0.0f) : Rgb(1.0f))
                           : filteredShadowTransmittance(scene, tracer, shadow, Media{});
    }
    const Rgb term = isBlack(through) ? Rgb(0.0f) : through * a2::blinnPhong(surface, light);
    if (tree) {
      RayTreeNode n;
      n.kind = RayKind::Shadow;
      n.parent = 0;
      n.origin = castShadow ? shadow.origin : sp.position;
      n.direction = light.l;
      n.t = std::isfinite(light.distance) ? light.distance : 0.0f;  // to the light (0: a directional one)
      n.intersected = true;
      n.shadowTransmittance = through;
      n.contribution = term;
      tree->nodes.push_back(n);
    }
    return term;
  }

  Camera camera_;
  int lightSamples_ = 16;
  bool filtered_ = false;
  std::unique_ptr<Accelerator> student_;
};

}  // namespace

TechniqueInfo raycastTechnique() {
  return {
      "raycast",
      "ray casting (Appel 1968): Blinn-Phong at the first hit, shadow rays to point and area lights",
      EffectSet{Effect::DirectLighting, Effect::HardShadows, Effect::SoftShadows, Effect::GlossyHighlights,
                Effect::Textures, Effect::Emission},
      1,
      {
          ParamDecl::integer("light_samples", 16, 1, 1024,
                             "shadow-ray samples per area light per pixel sample (soft-shadow quality)"),
          ParamDecl::choice("intersection", "auto", {"auto", "student", "framework"},
                            "student: brute force with your A2.2/A2.3 tests; framework: the chosen accelerator; "
                            "auto: student with -a none, else framework"),
          ParamDecl::choice("shadows", "filtered", {"filtered", "opaque"},
                            "filtered: shadow rays pass through transmissive surfaces, tinted by them and absorbed "
                            "inside (Beer-Lambert); opaque: every surface blocks light"),
      },
      []() -> std::unique_ptr<Technique> { return std::make_unique<Raycast>(); },
  };
}

}  // namespace ll
