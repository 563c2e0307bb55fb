#include "light_sampler.h"

#include <algorithm>
#include <cmath>


namespace ll::a6 {

LightSampler::LightSampler(const Scene& scene)
    : scene_(scene), areaLightOfObject_(scene.objects.size(), -1),
      count_(scene.lights.size() + scene.areaLights.size()), sky_(scene.environment.lightsScene()) {
  if (sky_) ++count_;
  for (size_t i = 0; i < scene.areaLights.size(); ++i)
    areaLightOfObject_[scene.areaLights[i].object] = static_cast<int>(i);
}

LightSample LightSampler::sample(float uChoice, Vec2 u, const Vec3& from) const {
  const auto index = std::min(static_cast<size_t>(uChoice * static_cast<float>(count_)), count_ - 1);
  const float choice = 1.0f / static_cast<float>(count_);
  LightSample s;
  if (index < scene_.lights.size()) {
    const Light& light = scene_.lights[index];
    s.kind = light.type == Light::Type::Point ? LightSample::Kind::Point : LightSample::Kind::Directional;
    s.position = light.position;
    s.direction = light.direction;
    s.emission = light.intensity;
    s.pdf = choice;
    s.castShadow = light.canBeOccluded;
    return s;
  }
  if (sky_ && index == count_ - 1) {
    const Environment::Sample sky = scene_.environment.sample(u);
    s.kind = LightSample::Kind::Area;
    s.position = from + kSkyDistance * sky.dir;
    s.normal = -sky.dir;
    s.emission = sky.radiance;
    s.pdf = choice * sky.pdf / (kSkyDistance * kSkyDistance);
    s.castShadow = true;
    s.sky = true;
    return s;
  }
  const AreaLight& light = scene_.areaLights[index - scene_.lights.size()];
  const LightPoint p = scene_.sampleAreaLight(light, u);
  s.kind = LightSample::Kind::Area;
  s.position = p.position;
  s.normal = p.normal;
  s.emission = p.emission;
  s.pdf = choice / light.area;
  s.material = &scene_.materials[scene_.objects[light.object].material];
  s.castShadow = light.canBeOccluded;
  return s;
}

float LightSampler::pdfSolidAngle(uint32_t prim, float distance, float cosLight) const {
  const int index = areaLightOfObject_[scene_.geometry.objectOf(prim)];
  if (index < 0 || !(cosLight > 0.0f)) return 0.0f;
  const float pdfArea = 1.0f / (static_cast<float>(count_) * scene_.areaLights[static_cast<size_t>(index)].area);
  return pdfArea * distance * distance / cosLight;
}

float LightSampler::pdfSky(const Vec3& dir) const {
  return sky_ ? scene_.environment.pdf(dir) / static_cast<float>(count_) : 0.0f;
}

}  // namespace ll::a6
