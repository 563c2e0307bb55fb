#include "render/raster_scene.h"

#include <algorithm>
#include <cmath>

namespace ll {

void addSphere(std::vector<RasterVertex>& out, const Sphere& s, int segments) {
  const int rings = std::max(segments / 2, 4);
  const auto vertex = [&](int i, int j) {
    const float theta = kPi * static_cast<float>(j) / static_cast<float>(rings) - kPi / 2;  // latitude
    const float phi = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
    const Vec3 n(std::cos(theta) * std::cos(phi), std::sin(theta), std::cos(theta) * std::sin(phi));
    return RasterVertex{s.center + s.radius * n, n,
                        Vec2(static_cast<float>(i) / static_cast<float>(segments),
                             static_cast<float>(j) / static_cast<float>(rings))};
  };
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const RasterVertex a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
      out.insert(out.end(), {a, c, b, a, d, c});
    }
}

RasterMesh buildRasterMesh(const Scene& scene, int sphereSegments) {
  const Geometry& g = scene.geometry;
  RasterMesh mesh;
  for (const SceneObject& object : scene.objects) {
    const int first = static_cast<int>(mesh.vertices.size());
    for (uint32_t prim = object.firstPrim; prim < object.firstPrim + object.primCount; ++prim) {
      if (!g.isTriangle(prim)) {
        addSphere(mesh.vertices, g.spheres[prim - g.triangleCount()], sphereSegments);
        continue;
      }
      const glm::uvec3& t = g.triangles[prim];
      const Vec3 cross = glm::cross(g.positions[t.y] - g.positions[t.x], g.positions[t.z] - g.positions[t.x]);
      const float doubleArea = glm::length(cross);
      if (!(doubleArea > 0.0f)) continue;  // a degenerate triangle covers no pixel and has no normal
      const Vec3 face = cross / doubleArea;
      for (uint32_t k : {t.x, t.y, t.z}) {
        // A vertex normal that is missing or zero (meshes with collapsed fans have them) falls back to the face's.
        const bool usable = !g.normals.empty() && glm::dot(g.normals[k], g.normals[k]) > 1e-12f;
        mesh.vertices.push_back(
            {g.positions[k], usable ? g.normals[k] : face, g.uvs.empty() ? Vec2(0.0f) : g.uvs[k]});
      }
    }
    mesh.ranges.emplace_back(first, static_cast<int>(mesh.vertices.size()) - first);
  }
  return mesh;
}

std::vector<RasterLight> rasterLights(const Scene& scene, int areaSamples) {
  std::vector<RasterLight> lights;
  for (const Light& l : scene.lights) {
    if (l.type == Light::Type::Point)
      lights.push_back({RasterLight::Kind::Point, l.position, Vec3(0.0f), l.intensity});
    else
      lights.push_back({RasterLight::Kind::Directional, -glm::normalize(l.direction), Vec3(0.0f), l.intensity});
  }
  const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(static_cast<double>(areaSamples)))));
  for (const AreaLight& a : scene.areaLights)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const LightPoint p = scene.sampleAreaLight(
            a, Vec2((static_cast<float>(i) + 0.5f) / static_cast<float>(n),
                    (static_cast<float>(j) + 0.5f) / static_cast<float>(n)));
        lights.push_back(
            {RasterLight::Kind::AreaSample, p.position, p.normal, a.emission * (a.area / static_cast<float>(n * n))});
      }
  return lights;
}

DepthRange rasterDepthRange(const Scene& scene, const Camera& camera) {
  const Bounds3 b = scene.geometry.sceneBounds();
  const Vec3 forward = glm::normalize(camera.target - camera.eye);
  float zMin = kInfinity, zMax = -kInfinity;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y, (corner & 4) ? b.max.z : b.min.z);
    const float z = glm::dot(p - camera.eye, forward);
    zMin = std::min(zMin, z);
    zMax = std::max(zMax, z);
  }
  DepthRange r;
  if (b.empty() || !(zMax > 0.0f)) return r;  // nothing in front of the camera: any range will do
  r.far = 1.01f * zMax;
  r.near = std::max(0.99f * zMin, 1e-3f * r.far);
  return r;
}

}  // namespace ll
