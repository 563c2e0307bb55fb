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

 protected:
  const Accelerator& accelerator(const RenderContext& ctx) const override {
    return student_ ? *student_ : ctx.accel;
  }

  Rgb renderSample(const RenderContext& ctx, const PixelSample& s, const Tracer& tracer) const override {
    const Scene& scene = ctx.scene;
    Ray ray = a2::cameraRay(camera_, s.position.x, s.position.y);
    Hit hit;
    if (!tracer.intersect(ray, hit, RayKind::Camera)) return scene.environment.radiance(glm::normalize(ray.dir));
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
      radiance += shade(scene, tracer, sp, surface, in, light.canBeOccluded);
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
        radiance += shade(scene, tracer, sp, surface, in, light.canBeOccluded);
      }
    }
    return radiance;
  }

 private:
  // One light's Blinn-Phong term, if the light is in front of the surface and visible.
  Rgb shade(const Scene& scene, const Tracer& tracer, const SurfacePoint& sp, const a2::ShadingInput& surface,
            const a2::LightInput& light, bool castShadow) const {
    if (glm::dot(sp.geometricNormal, light.l) <= 0.0f) return Rgb(0.0f);  // the surface itself blocks it
    if (!castShadow) return a2::blinnPhong(surface, light);
    const Ray shadow = a2::shadowRay(sp, light.l, light.distance);
    if (!filtered_) return tracer.occluded(shadow) ? Rgb(0.0f) : a2::blinnPhong(surface, light);
    const Rgb through = filteredShadowTransmittance(scene, tracer, shadow, Media{});
    return isBlack(through) ? Rgb(0.0f) : through * a2::blinnPhong(surface, light);
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
