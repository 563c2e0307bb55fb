#include "scene/scene.h"

#include <algorithm>

namespace ll {

namespace {

// A convex or planar object cannot shadow itself.
bool selfShadowing(const SceneObject& o) { return !(o.type == "sphere" || o.type == "quad" || o.type == "polygon"); }

Bounds3 objectBounds(const Scene& s, const SceneObject& o) {
  Bounds3 b;
  for (uint32_t p = o.firstPrim; p < o.firstPrim + o.primCount; ++p) b.extend(s.geometry.bounds(p));
  return b;
}

bool overlap(const Bounds3& a, const Bounds3& b) {
  return !(a.empty() || b.empty()) && a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y &&
         b.min.y <= a.max.y && a.min.z <= b.max.z && b.min.z <= a.max.z;
}

// Can some object block light travelling from `source` (a box around the
// light; empty for a directional light) to a point of some receiver? A
// blocker must touch the box spanned by the receiver and the source
// (conservative; for directional lights any other object may block). The
// emitting object `emitter` (or none) blocks only if it can shadow itself.
bool lightCanBeOccluded(const Scene& s, const std::vector<Bounds3>& boxes, const Bounds3& source,
                        uint32_t emitter) {
  for (uint32_t r = 0; r < s.objects.size(); ++r) {
    if (s.objects[r].primCount == 0) continue;
    if (selfShadowing(s.objects[r])) return true;
    Bounds3 span = boxes[r];
    span.extend(source);
    for (uint32_t o = 0; o < s.objects.size(); ++o) {
      if (o == r || s.objects[o].primCount == 0) continue;
      if (o == emitter && !selfShadowing(s.objects[o])) continue;
      if (source.empty() || overlap(span, boxes[o])) return true;
    }
  }
  return false;
}

EffectSet analyseEffects(const Scene& s) {
  EffectSet e;
  std::vector<bool> used(s.materials.size(), false);
  for (const SceneObject& o : s.objects)
    if (o.primCount > 0) used[o.material] = true;
  const bool hasLights = !s.lights.empty();
  const bool hasAreaLights = !s.areaLights.empty() || s.environment.lightsScene();  // the sky lights like an area light
  bool hardShadows = false, softShadows = false;
  for (const Light& l : s.lights) hardShadows = hardShadows || l.canBeOccluded;
  for (const AreaLight& l : s.areaLights) softShadows = softShadows || l.canBeOccluded;
  if (hasLights || !s.areaLights.empty()) e.add(Effect::DirectLighting);
  bool anySurface = false;
  for (const SceneObject& o : s.objects) anySurface = anySurface || o.primCount > 0;
  if (s.environment.lightsScene() && anySurface) e.add(Effect::SkyLight);
  if (hardShadows) e.add(Effect::HardShadows);
  if (softShadows) e.add(Effect::SoftShadows);
  bool diffuse = false, specular = false;
  for (size_t i = 0; i < s.materials.size(); ++i) {
    if (!used[i]) continue;
    const Material& m = s.materials[i];
    // A rough metal or rough glass scatters glossily; its mirror and clear-glass fields are only the local
    // model's specular limit (material.h), so it makes glossy reflection possible, not mirror reflection or
    // refraction -- as the path tracer's light-path classes count it.
    if (m.reflectsMirror() && !m.glossyScattering()) e.add(Effect::MirrorReflection);
    if (m.transmits() && !m.glossyScattering()) e.add(Effect::Refraction);
    if (m.transmits() && m.dispersive()) e.add(Effect::Dispersion);
    if (m.glossy() && (hasLights || hasAreaLights)) e.add(Effect::GlossyHighlights);
    if (m.glossyScattering()) e.add(Effect::GlossyReflection);
    if (m.texture.kind != Texture::Kind::None) e.add(Effect::Textures);
    if (m.emits()) e.add(Effect::Emission);
    if (!isBlack(m.kd) || m.texture.kind == Texture::Kind::Checker) diffuse = true;
    if (!m.glossyScattering() && (m.reflectsMirror() || m.transmits() || m.model == BsdfModel::Conductor))
      specular = true;
  }
  // Light bouncing between surfaces needs two surfaces that see each other: as for shadows, more than one
  // convex object.
  const bool interreflects = s.objects.size() > 1 || (s.objects.size() == 1 && selfShadowing(s.objects[0]));
  if (diffuse && (hasLights || hasAreaLights) && interreflects) e.add(Effect::DiffuseInterreflection);
  // A mirror or glass that lights a diffuse surface (L S+ D): the same two-surface condition.
  if (diffuse && specular && (hasLights || hasAreaLights) && interreflects) e.add(Effect::Caustics);
  return e;
}

}  // namespace

void Scene::finalize() {
  areaLights.clear();
  for (uint32_t i = 0; i < objects.size(); ++i) {
    const SceneObject& o = objects[i];
    const Material& m = materials[o.material];
    if (!m.emits() || o.primCount == 0) continue;
    AreaLight light;
    light.object = i;
    light.emission = m.emission;
    for (uint32_t p = o.firstPrim; p < o.firstPrim + o.primCount; ++p) {
      const float a = geometry.area(p);
      if (!(a > 0.0f)) continue;  // degenerate triangles cannot emit
      light.area += a;
      light.prims.push_back(p);
      light.cdf.push_back(light.area);
    }
    if (light.area > 0.0f) areaLights.push_back(std::move(light));
  }
  std::vector<Bounds3> boxes;
  for (const SceneObject& o : objects) boxes.push_back(objectBounds(*this, o));
  const auto none = static_cast<uint32_t>(objects.size());
  for (Light& l : lights) {
    Bounds3 source;
    if (l.type == Light::Type::Point) source.extend(l.position);
    l.canBeOccluded = lightCanBeOccluded(*this, boxes, source, none);
  }
  for (AreaLight& l : areaLights) l.canBeOccluded = lightCanBeOccluded(*this, boxes, boxes[l.object], l.object);
  effects = analyseEffects(*this);
  hasMirrors = hasTransmission = false;
  for (const SceneObject& o : objects) {
    if (o.primCount == 0) continue;
    hasMirrors = hasMirrors || materials[o.material].reflectsMirror();
    hasTransmission = hasTransmission || materials[o.material].transmits();
  }
}

SurfacePoint Scene::surfacePoint(const Ray& ray, const Hit& hit) const {
  SurfacePoint sp;
  sp.prim = hit.prim;
  sp.object = geometry.objectOf(hit.prim);
  sp.material = &materials[objects[sp.object].material];
  if (geometry.isTriangle(hit.prim)) {
    const glm::uvec3& tri = geometry.triangles[hit.prim];
    const float b0 = 1.0f - hit.b1 - hit.b2;
    const Vec3& p0 = geometry.positions[tri.x];
    const Vec3& p1 = geometry.positions[tri.y];
    const Vec3& p2 = geometry.positions[tri.z];
    // Barycentric position is more accurate than origin + t*dir far from the eye.
    sp.position = b0 * p0 + hit.b1 * p1 + hit.b2 * p2;
    sp.geometricNormal = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    sp.shadingNormal = sp.geometricNormal;
    if (!geometry.normals.empty()) {
      const Vec3 n = b0 * geometry.normals[tri.x] + hit.b1 * geometry.normals[tri.y] +
                     hit.b2 * geometry.normals[tri.z];
      const float len = glm::length(n);
      if (len > 0.0f) sp.shadingNormal = n / len;
      if (glm::dot(sp.shadingNormal, sp.geometricNormal) < 0.0f) sp.shadingNormal = -sp.shadingNormal;
    }
    if (!geometry.uvs.empty())
      sp.uv = b0 * geometry.uvs[tri.x] + hit.b1 * geometry.uvs[tri.y] + hit.b2 * geometry.uvs[tri.z];
    else
      sp.uv = Vec2(hit.b1, hit.b2);
  } else {
    const Sphere& s = geometry.spheres[hit.prim - geometry.triangleCount()];
    const Vec3 local = ray.at(hit.t) - s.center;
    sp.geometricNormal = glm::normalize(local);
    sp.position = s.center + s.radius * sp.geometricNormal;  // reprojected onto the surface
    sp.shadingNormal = sp.geometricNormal;
    const Vec3& n = sp.geometricNormal;
    sp.uv = Vec2(0.5f + std::atan2(n.z, n.x) / (2.0f * kPi),
                 0.5f + std::asin(std::clamp(n.y, -1.0f, 1.0f)) / kPi);
  }
  return sp;
}

LightPoint Scene::sampleAreaLight(const AreaLight& light, Vec2 u) const {
  // Choose a primitive proportionally to area, then reuse u.x's remainder.
  const float target = u.x * light.area;
  const auto it = std::upper_bound(light.cdf.begin(), light.cdf.end(), target);
  const size_t i = std::min(static_cast<size_t>(it - light.cdf.begin()), light.prims.size() - 1);
  const float lo = i == 0 ? 0.0f : light.cdf[i - 1];
  const float ux = std::clamp((target - lo) / (light.cdf[i] - lo), 0.0f, 0.99999994f);
  const uint32_t prim = light.prims[i];
  LightPoint lp;
  lp.emission = light.emission;
  if (geometry.isTriangle(prim)) {
    const glm::uvec3& tri = geometry.triangles[prim];
    const Vec3 &p0 = geometry.positions[tri.x], &p1 = geometry.positions[tri.y],
               &p2 = geometry.positions[tri.z];
    // Uniform on the triangle (square-root parameterisation).
    const float su = std::sqrt(ux);
    const float b1 = su * (1.0f - u.y), b2 = su * u.y;
    lp.position = (1.0f - b1 - b2) * p0 + b1 * p1 + b2 * p2;
    lp.normal = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  } else {
    const Sphere& s = geometry.spheres[prim - geometry.triangleCount()];
    const float z = 1.0f - 2.0f * ux, r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * u.y;
    lp.normal = Vec3(r * std::cos(phi), r * std::sin(phi), z);
    lp.position = s.center + s.radius * lp.normal;
  }
  return lp;
}

}  // namespace ll
