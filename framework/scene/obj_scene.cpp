// OBJ + MTL files loaded directly as scenes, through tinyobjloader.
#include <filesystem>
#include <map>
#include <sstream>

#include <tiny_obj_loader.h>

#include "core/error.h"
#include "core/files.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"

namespace ll {

namespace fs = std::filesystem;

namespace {

Rgb rgb(const tinyobj::real_t* c) { return glm::max(Rgb(c[0], c[1], c[2]), Rgb(0.0f)); }

// MTL -> material model. illum 3/5: mirror-like Ks; illum 4/6/7 or d < 1: a
// dielectric with transmittance Tf (or 1 - d) and index Ni.
Material convert(const tinyobj::material_t& m, const std::string& baseDir) {
  Material out;
  out.name = m.name;
  out.ka = rgb(m.ambient);
  out.kd = rgb(m.diffuse);
  out.ks = rgb(m.specular);
  out.shininess = std::max(0.0f, static_cast<float>(m.shininess));
  out.emission = rgb(m.emission);
  out.ior = m.ior > 0 ? static_cast<float>(m.ior) : 1.0f;
  if (m.illum == 3 || m.illum == 5) out.mirror = out.ks;
  const bool refractive = m.illum == 4 || m.illum == 6 || m.illum == 7 || m.dissolve < 1.0f;
  if (refractive) {
    const Rgb tf = rgb(m.transmittance);
    out.transmission = isBlack(tf) ? Rgb(1.0f - static_cast<float>(m.dissolve)) : tf;
  }
  if (!m.diffuse_texname.empty()) {
    const std::string file = (fs::path(baseDir) / m.diffuse_texname).lexically_normal().string();
    out.texture.kind = Texture::Kind::Image;
    out.texture.image = std::make_shared<Image>(loadImage(file));
  }
  return out;
}

}  // namespace

Scene loadObjScene(const std::string& path) {
  // Checked whole before tinyobjloader reads it, which skips lines it does not know (binary data too).
  checkTextFile(path, "OBJ scene", kMaxMeshFileBytes);
  const std::string baseDir = fs::path(path).parent_path().string();
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.mtl_search_path = baseDir;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) {
    std::string err = reader.Error();
    while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
    throwUserError(path + ": cannot read OBJ: " + (err.empty() ? "unknown error" : err));
  }
  const auto& attrib = reader.GetAttrib();
  Scene scene;
  scene.path = path;
  for (const auto& m : reader.GetMaterials()) scene.materials.push_back(convert(m, baseDir));
  const auto defaultMaterial = static_cast<uint32_t>(scene.materials.size());
  Material grey;
  grey.name = "default";
  grey.kd = grey.ka = Rgb(0.7f);
  scene.materials.push_back(grey);

  Geometry& g = scene.geometry;
  const bool hasNormals = !attrib.normals.empty();
  const bool hasUvs = !attrib.texcoords.empty();
  // tinyobjloader resolves negative (relative) indices but does not check any against the counts.
  const auto checkIndex = [&](int index, size_t count, size_t line, const char* what) {
    if (index < 0 || static_cast<size_t>(index) >= count)
      throwUserError(path + ": face " + std::to_string(line) + " uses " + what + " " + std::to_string(index + 1) +
                     ", but the file has " + std::to_string(count));
  };
  size_t faceNumber = 0;  // over all shapes, 1-based in messages
  for (const auto& shape : reader.GetShapes()) {
    std::map<int, uint32_t> objectOfMaterial;  // one scene object per (shape, material)
    const auto& mesh = shape.mesh;
    size_t first = 0;  // of face f's indices in mesh.indices
    for (size_t f = 0; f < mesh.num_face_vertices.size(); first += mesh.num_face_vertices[f], ++f) {
      ++faceNumber;
      if (mesh.num_face_vertices[f] != 3 || first + 3 > mesh.indices.size()) continue;  // not a triangle: nothing to hit
      for (size_t k = 0; k < 3; ++k) {
        const tinyobj::index_t idx = mesh.indices[first + k];
        checkIndex(idx.vertex_index, attrib.vertices.size() / 3, faceNumber, "vertex");
        if (hasNormals && idx.normal_index >= 0) checkIndex(idx.normal_index, attrib.normals.size() / 3, faceNumber, "normal");
        if (hasUvs && idx.texcoord_index >= 0)
          checkIndex(idx.texcoord_index, attrib.texcoords.size() / 2, faceNumber, "texture coordinate");
      }
      int mat = f < mesh.material_ids.size() ? mesh.material_ids[f] : -1;
      if (mat >= static_cast<int>(defaultMaterial)) mat = -1;  // not among the materials read
      auto [it, added] = objectOfMaterial.try_emplace(mat, static_cast<uint32_t>(scene.objects.size()));
      if (added) {
        SceneObject o;
        o.type = "mesh";
        o.name = shape.name.empty() ? "obj shape" : shape.name;
        if (mat >= 0) o.name += " (" + scene.materials[static_cast<size_t>(mat)].name + ")";
        o.material = mat >= 0 ? static_cast<uint32_t>(mat) : defaultMaterial;
        scene.objects.push_back(o);
      }
      glm::uvec3 tri;
      for (int k = 0; k < 3; ++k) {
        const tinyobj::index_t idx = mesh.indices[first + static_cast<size_t>(k)];
        tri[k] = static_cast<unsigned>(g.positions.size());
        const auto vi = static_cast<size_t>(idx.vertex_index);
        const Vec3 p(attrib.vertices[3 * vi], attrib.vertices[3 * vi + 1], attrib.vertices[3 * vi + 2]);
        if (!isFinite(p)) throwUserError(path + ": vertex " + std::to_string(vi + 1) + " is not finite");
        if (!withinSceneLimits(p)) {
          std::ostringstream s;
          s << path << ": vertex " << vi + 1 << " reaches " << largestMagnitude(p)
            << " units: overflow (a scene must stay within +-1e8 units; scale it down)";
          throwUserError(s.str());
        }
        g.positions.push_back(p);
        if (hasNormals) {
          const auto ni = idx.normal_index;
          g.normals.push_back(ni < 0 ? Vec3(0.0f)
                                     : Vec3(attrib.normals[3 * static_cast<size_t>(ni)],
                                            attrib.normals[3 * static_cast<size_t>(ni) + 1],
                                            attrib.normals[3 * static_cast<size_t>(ni) + 2]));
        }
        if (hasUvs) {
          const auto ti = idx.texcoord_index;
          g.uvs.push_back(ti < 0 ? Vec2(0.0f)
                                 : Vec2(attrib.texcoords[2 * static_cast<size_t>(ti)],
                                        attrib.texcoords[2 * static_cast<size_t>(ti) + 1]));
        }
      }
      if (glm::length(glm::cross(g.positions[tri.y] - g.positions[tri.x], g.positions[tri.z] - g.positions[tri.x])) ==
          0.0f)
        continue;  // zero-area: can be neither hit nor shaded
      g.triangles.push_back(tri);
      g.triangleObject.push_back(it->second);
    }
  }
  if (g.triangles.empty()) throwUserError(path + ": the OBJ file has no faces");
  // Objects must own contiguous primitive ranges: sort triangles by object.
  std::vector<uint32_t> order(g.triangles.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return g.triangleObject[a] < g.triangleObject[b]; });
  std::vector<glm::uvec3> tris;
  std::vector<uint32_t> owners;
  for (uint32_t i : order) {
    tris.push_back(g.triangles[i]);
    owners.push_back(g.triangleObject[i]);
  }
  g.triangles = std::move(tris);
  g.triangleObject = std::move(owners);
  for (uint32_t p = 0; p < g.triangleCount(); ++p) {
    SceneObject& o = scene.objects[g.triangleObject[p]];
    if (o.primCount == 0) o.firstPrim = p;
    ++o.primCount;
  }

  // A camera framing the bounds from +z, and a light at the eye if nothing emits.
  const Bounds3 b = g.sceneBounds();
  const float radius = std::max(0.5f * b.diagonal(), 1e-3f);  // vertices within the scene limits: finite
  scene.camera.fovYDeg = 45.0f;
  scene.camera.target = b.center();
  scene.camera.eye = b.center() + Vec3(0.0f, 0.25f * radius, 2.6f * radius);
  scene.ambient = Rgb(0.1f);
  scene.finalize();
  if (scene.areaLights.empty()) {
    Light l;
    l.position = scene.camera.eye + Vec3(0.0f, radius, 0.0f);
    const float d = glm::length(l.position - scene.camera.target);
    l.intensity = Rgb(d * d);
    scene.lights.push_back(l);
    scene.finalize();
  }
  return scene;
}

}  // namespace ll
