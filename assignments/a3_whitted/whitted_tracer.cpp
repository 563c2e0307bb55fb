#include "whitted_tracer.h"

#include <algorithm>
#include <cmath>

#include "render/ray_offset.h"
#include "render/shadow_transmittance.h"
#include "render/technique.h"

namespace ll::a3 {

float fresnelSchlick(float cosI, float n1, float n2) {
  float c = std::clamp(cosI, 0.0f, 1.0f);
  if (n1 > n2) {  // use the cosine on the thinner side: the transmitted one
    const float eta = n1 / n2;
    const float sin2T = eta * eta * (1.0f - c * c);
    if (sin2T >= 1.0f) return 1.0f;
    c = std::sqrt(1.0f - sin2T);
  }
  const float r0 = ((n1 - n2) / (n1 + n2)) * ((n1 - n2) / (n1 + n2));
  const float m = 1.0f - c;
  return r0 + (1.0f - r0) * m * m * m * m * m;
}

WhittedTracer::WhittedTracer(const Scene& scene, const Tracer& tracer, const WhittedSettings& settings, Rng& rng,
                             RayTree* tree)
    : scene_(scene),
      tracer_(tracer),
      settings_(settings),
      rng_(rng),
      tree_(tree),
      transmissive_(scene.hasTransmission) {}

std::optional<Surface> WhittedTracer::intersect(const Ray& ray, const PathState& path) const {
  Hit hit;
  const bool found = tracer_.intersect(ray, hit, path.kind);
  RayTreeNode* node = tree_ && path.node >= 0 ? &tree_->nodes[static_cast<size_t>(path.node)] : nullptr;
  if (node) node->intersected = true;
  if (!found) return std::nullopt;
  Surface s;
  s.sp = scene_.surfacePoint(ray, hit);
  s.d = glm::normalize(ray.dir);
  s.t = hit.t * glm::length(ray.dir);
  s.entering = glm::dot(s.sp.geometricNormal, s.d) < 0.0f;
  s.ng = faceTowards(s.sp.geometricNormal, -s.d);
  s.n = faceTowards(s.sp.shadingNormal, -s.d);
  const Material& m = s.material();
  // The media on both sides: entering a dielectric pushes it, leaving pops it.
  const uint32_t id = materialIndex(&m);
  if (m.transmits()) {
    if (s.entering) {
      s.n1 = path.media.ior(scene_);
      s.mediaBehind = path.media.with(id);
      s.n2 = m.ior;
    } else {
      s.n1 = m.ior;
      s.mediaBehind = path.media.without(id);
      s.n2 = s.mediaBehind.ior(scene_);
    }
  } else {
    s.n1 = s.n2 = path.media.ior(scene_);
    s.mediaBehind = path.media;
  }
  // Beer-Lambert over the segment, in the medium the ray travelled through.
  const Rgb sigma = path.media.absorption(scene_);
  if (!isBlack(sigma)) s.absorption = glm::exp(-sigma * s.t);
  s.path = path;
  s.path.throughput = path.throughput * s.absorption;
  if (node) {
    node->hit = true;
    node->t = s.t;
    node->position = s.sp.position;
    node->normal = s.n;
    node->object = scene_.objects[s.sp.object].name;
    node->material = m.name;
    node->entering = s.entering;
    node->n1 = s.n1;
    node->n2 = s.n2;
    node->absorption = s.absorption;
    if (m.transmits()) {  // total internal reflection is a property of the geometry: recorded here
      const float cosI = std::clamp(glm::dot(-s.d, s.n), 0.0f, 1.0f);
      node->totalInternalReflection = (s.n1 / s.n2) * (s.n1 / s.n2) * (1.0f - cosI * cosI) >= 1.0f;
    }
  }
  return s;
}

Rgb WhittedTracer::emitted(const Surface& s) const {
  const Rgb e = s.entering ? s.material().emission : Rgb(0.0f);
  if (tree_ && s.path.node >= 0) tree_->nodes[static_cast<size_t>(s.path.node)].local += e;
  return e;
}

Rgb WhittedTracer::lightTerm(const Surface& s, Vec3 l, float distance, Rgb intensity, bool castShadow) const {
  if (glm::dot(s.ng, l) <= 0.0f) return Rgb(0.0f);  // the surface itself blocks it
  Rgb visible(1.0f);
  if (castShadow) {
    Ray shadow;
    shadow.origin = offsetRayOrigin(s.sp.position, faceTowards(s.sp.geometricNormal, l));
    shadow.dir = l;
    shadow.tmin = 0.0f;
    shadow.tmax = std::isinf(distance) ? kInfinity : distance * (1.0f - 1e-4f);  // stop short of the light
    visible = shadowTransmittance(shadow, s);
    if (isBlack(visible)) return Rgb(0.0f);
  }
  const Material& m = s.material();
  const float falloff = std::isinf(distance) ? 1.0f : 1.0f / (distance * distance);
  const Rgb irradiance = intensity * falloff;  // I / r^2
  const Vec3 v = -s.d;
  const Vec3 h = glm::normalize(v + l);
  const float diffuse = std::max(0.0f, glm::dot(s.n, l));
  const float specular = std::pow(std::max(0.0f, glm::dot(s.n, h)), m.shininess);
  return visible * (m.diffuse(s.sp.uv) * irradiance * diffuse + m.ks * irradiance * specular);
}

Rgb WhittedTracer::shadowTransmittance(const Ray& shadow, const Surface& s) const {
  const int node = tree_ && s.path.node >= 0 ? addNode(RayKind::Shadow, shadow, s.path, s.path.node, Rgb(0.0f)) : -1;
  Rgb through(1.0f);
  if (!settings_.filteredShadows || !transmissive_) {
    if (tracer_.occluded(shadow)) through = Rgb(0.0f);
  } else {
    // Through transmissive surfaces, tinted by them and absorbed by the media between (Beer-Lambert).
    through = filteredShadowTransmittance(scene_, tracer_, shadow, s.path.media);
  }
  if (node >= 0) tree_->nodes[static_cast<size_t>(node)].shadowTransmittance = through;
  return through;
}

Rgb WhittedTracer::local(const Surface& s) const {
  const Material& m = s.material();
  Rgb radiance = m.ka * scene_.ambient;  // the lecture's ka * Ia
  if (!isBlack(m.kd) || !isBlack(m.ks) || m.texture.kind != Texture::Kind::None) {  // else no light is reflected
    for (const Light& light : scene_.lights) {
      if (light.type == Light::Type::Point) {
        const Vec3 d = light.position - s.sp.position;
        const float distance = glm::length(d);
        radiance += lightTerm(s, d / distance, distance, light.intensity, light.canBeOccluded);
      } else {
        radiance += lightTerm(s, -light.direction, kInfinity, light.intensity, light.canBeOccluded);
      }
    }
    const int n = settings_.lightSamples;
    for (const AreaLight& light : scene_.areaLights) {
      for (int k = 0; k < n; ++k) {
        const LightPoint lp = scene_.sampleAreaLight(light, stratifiedSample(k, n, rng_));
        const Vec3 target = offsetRayOrigin(lp.position, faceTowards(lp.normal, s.sp.position - lp.position));
        const Vec3 d = target - s.sp.position;
        const float distance = glm::length(d);
        if (!(distance > 0.0f)) continue;
        const Vec3 l = d / distance;
        const float cosLight = glm::dot(lp.normal, -l);
        if (cosLight <= 0.0f) continue;  // behind the emitting side
        const Rgb intensity = lp.emission * (light.area / static_cast<float>(n)) * cosLight / kPi;
        radiance += lightTerm(s, l, distance, intensity, light.canBeOccluded);
      }
    }
  }
  if (tree_ && s.path.node >= 0) tree_->nodes[static_cast<size_t>(s.path.node)].local += radiance;
  return radiance;
}

float WhittedTracer::fresnel(const Surface& s) const {
  const float cosI = std::clamp(glm::dot(-s.d, s.n), 0.0f, 1.0f);
  const float eta = s.n1 / s.n2;
  const bool tir = eta * eta * (1.0f - cosI * cosI) >= 1.0f;
  const float f = tir ? 1.0f
                  : settings_.schlick ? fresnelSchlick(cosI, s.n1, s.n2)
                                      : std::clamp(fresnelDielectric(cosI, s.n1, s.n2).unpolarized(), 0.0f, 1.0f);
  if (tree_ && s.path.node >= 0) {
    RayTreeNode& node = tree_->nodes[static_cast<size_t>(s.path.node)];
    node.fresnel = f;
    node.totalInternalReflection = tir;
  }
  return f;
}

int WhittedTracer::addNode(RayKind kind, const Ray& ray, const PathState& parentPath, int parentNode,
                           Rgb throughput) const {
  RayTreeNode node;
  node.kind = kind;
  node.parent = parentNode;
  node.depth = kind == RayKind::Shadow ? parentPath.depth : parentPath.depth + 1;
  node.origin = ray.origin;
  node.direction = glm::normalize(ray.dir);
  node.throughput = throughput;
  tree_->nodes.push_back(node);
  return static_cast<int>(tree_->nodes.size()) - 1;
}

Rgb WhittedTracer::trace(const Ray& ray, RayKind kind, const Surface& from, Rgb weight) const {
  if ((kind == RayKind::Refraction && settings_.skipRefraction) ||
      (kind == RayKind::Reflection && !from.path.refracted && settings_.skipMirrorReflection))
    return Rgb(0.0f);
  PathState child;
  child.refracted = from.path.refracted || kind == RayKind::Refraction;
  child.depth = from.path.depth + 1;
  child.throughput = from.path.throughput * weight;
  child.media = kind == RayKind::Refraction ? from.mediaBehind : from.path.media;
  child.kind = kind;
  if (tree_ && from.path.node >= 0) child.node = addNode(kind, ray, from.path, from.path.node, child.throughput);
  const Rgb l = radiance(*this, ray, child);
  if (child.node >= 0) tree_->nodes[static_cast<size_t>(child.node)].radiance = l;
  return weight * l;
}

Rgb WhittedTracer::traceCamera(const Ray& ray) const {
  PathState path;
  if (tree_) {
    RayTreeNode root;
    root.origin = ray.origin;
    root.direction = glm::normalize(ray.dir);
    tree_->nodes.push_back(root);
    path.node = static_cast<int>(tree_->nodes.size()) - 1;
  }
  const Rgb l = radiance(*this, ray, path);
  if (tree_) {
    tree_->nodes[static_cast<size_t>(path.node)].radiance = l;
    for (RayTreeNode& n : tree_->nodes) n.contribution = n.throughput * n.absorption * n.local;
    tree_->pixel = l;
  }
  return l;
}

}  // namespace ll::a3
