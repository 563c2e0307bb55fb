#include "scene/scene_loader.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/files.h"
#include "scene/conductor_fresnel.h"
#include "scene/json_document.h"
#include "scene/mesh_file.h"
#include "scene/named_metals.h"
#include "scene/scene_limits.h"

namespace ll {

namespace fs = std::filesystem;

namespace {

// An object transform: points by `m`, normals by the inverse transpose.
struct Transform {
  Mat4 m{1.0f};
  Mat3 normal{1.0f};
  Vec3 point(const Vec3& p) const { return Vec3(m * Vec4(p, 1.0f)); }
  Vec3 dir(const Vec3& n) const { return glm::normalize(normal * n); }
  bool uniformScale(float& s) const {
    const float sx = glm::length(Vec3(m[0])), sy = glm::length(Vec3(m[1])), sz = glm::length(Vec3(m[2]));
    s = sx;
    return std::abs(sx - sy) <= 1e-5f * sx && std::abs(sx - sz) <= 1e-5f * sx;
  }
};

Transform parseTransform(const JsonNode& obj) {
  Transform t;
  if (!obj.has("transform")) return t;
  const JsonNode n = obj.child("transform");
  n.allowOnly({"scale", "rotate_deg", "translate", "matrix"});
  if (n.has("matrix")) {
    if (n.has("scale") || n.has("rotate_deg") || n.has("translate"))
      n.fail(n.what() + " takes either 'matrix' or scale/rotate_deg/translate, not both");
    const JsonNode m = n.child("matrix");
    if (!m.json().is_array() || m.size() != 16) m.fail(m.what() + " must be 16 numbers (4x4, row-major)");
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) t.m[c][r] = m.at(static_cast<size_t>(4 * r + c)).asNumber();
  } else {
    Vec3 scale(1.0f);
    if (n.has("scale")) {
      const JsonNode s = n.child("scale");
      scale = s.json().is_number() ? Vec3(s.asNumber()) : s.asVec3();
      if (minComponent(glm::abs(scale)) <= 0.0f) s.fail(s.what() + " must be non-zero on every axis");
    }
    const Vec3 rot = n.vec3("rotate_deg", Vec3(0.0f));
    const Vec3 move = n.vec3("translate", Vec3(0.0f));
    Mat4 m = glm::translate(Mat4(1.0f), move);
    m = glm::rotate(m, radians(rot.z), Vec3(0, 0, 1));
    m = glm::rotate(m, radians(rot.y), Vec3(0, 1, 0));
    m = glm::rotate(m, radians(rot.x), Vec3(1, 0, 0));
    t.m = glm::scale(m, scale);
  }
  const Mat3 linear(t.m);
  if (std::abs(glm::determinant(linear)) < 1e-20f) n.fail(n.what() + " is singular (zero scale?)");
  t.normal = glm::transpose(glm::inverse(linear));
  return t;
}

// The file a string node names, relative to the scene's folder; fails at the node ("<what> not found: ...")
// if it does not exist.
std::string sceneRelativeFile(const JsonNode& n, const std::string& baseDir, const std::string& what) {
  const std::string file = (fs::path(baseDir) / n.json().get<std::string>()).lexically_normal().string();
  std::error_code ec;  // (a name too long for the system: a message, not a filesystem_error)
  if (!fs::exists(file, ec)) {  // the full path, so a name relative to the scene's folder is not misread
    std::error_code ec2;
    const fs::path absolute = fs::absolute(file, ec2).lexically_normal();
    n.fail(what + " not found: " + (ec || ec2 ? file : absolute.string()) + (ec ? " (" + ec.message() + ")" : ""));
  }
  return file;
}

Texture parseTexture(const JsonNode& mat, const std::string& baseDir) {
  Texture tex;
  if (!mat.has("texture")) return tex;
  const JsonNode n = mat.child("texture");
  if (n.json().is_string()) {
    const std::string file = sceneRelativeFile(n, baseDir, "texture file");
    tex.kind = Texture::Kind::Image;
    tex.image = std::make_shared<Image>(loadImage(file));
    return tex;
  }
  n.allowOnly({"type", "squares", "color_a", "color_b"});
  const std::string type = n.string("type");
  if (type != "checker") n.child("type").fail("unknown texture type '" + type + "' (allowed: checker, or a file path)");
  tex.kind = Texture::Kind::Checker;
  tex.squares = n.has("squares") ? n.child("squares").asVec2() : Vec2(8.0f);
  if (minComponent(Vec3(tex.squares, 1.0f)) <= 0.0f) n.child("squares").fail("checker squares must be > 0");
  tex.colorA = n.color("color_a", Rgb(1.0f));
  tex.colorB = n.color("color_b", Rgb(0.0f));
  return tex;
}

// The local model's stand-ins for a conductor (rasterizer, ray casting, Whitted): its Fresnel colour at normal
// incidence as mirror, ambient reflectance (the surroundings a metal reflects, where nothing is traced) and
// Blinn-Phong highlight, the highlight's exponent matched to the roughness (p = 2 / alpha^2 - 2, Walter et
// al. 2007), capped for a smooth metal.
void conductorLocalLimit(Material& m) {
  const Rgb f0 = conductorNormalReflectance(m.eta, m.k);
  m.mirror = f0;
  m.ka = f0;
  m.ks = f0;
  m.shininess = m.roughness >= kSmoothRoughness ? std::clamp(2.0f / (m.roughness * m.roughness) - 2.0f, 1.0f, 1e4f)
                                                : 1e4f;
}

// A colour or a measured spectrum: [r, g, b], or {"spectrum": "file.csv", "column": "name", "scale": 1}
// (file relative to the scene; data/spectra/README.md). Returns the RGB (the spectrum's projection) and
// sets `spectrum` for a spectrum.
Rgb colorOrSpectrum(const JsonNode& n, const std::string& key, Rgb fallback, const std::string& baseDir,
                    std::shared_ptr<const Spectrum>& spectrum) {
  if (!n.has(key) || !n.child(key).json().is_object()) return n.color(key, fallback);
  const JsonNode c = n.child(key);
  c.allowOnly({"spectrum", "column", "scale"});
  const JsonNode fileNode = c.child("spectrum");
  if (!fileNode.json().is_string()) fileNode.fail(fileNode.what() + " must be a file name (a .csv spectral table)");
  const std::string file = sceneRelativeFile(fileNode, baseDir, "spectrum file");
  const SpectrumTable table = loadSpectraCsv(file);
  const std::string column = c.string("column");
  const float scale = c.number("scale", 1.0f, 0.0f, 1e6f);
  for (size_t i = 0; i < table.names.size(); ++i) {
    if (table.names[i] != column) continue;
    Spectrum sp = table.columns[i];
    for (float& v : sp.value) v *= scale;
    spectrum = std::make_shared<const Spectrum>(std::move(sp));
    return glm::max(reflectanceToRgb(*spectrum), Rgb(0.0f));
  }
  c.child("column").fail("no column '" + column + "' in " + file + " (allowed: " + joinNames(table.names) + ")");
}

// "ior": a number, or {"cauchy": [n_d, B]}: the index at 587.6 nm and Cauchy's B in square micrometres.
void parseIor(const JsonNode& n, Material& m, float fallback) {
  if (!n.has("ior") || !n.child("ior").json().is_object()) {
    m.ior = n.number("ior", fallback, 1e-3f, 100.0f);
    return;
  }
  const JsonNode c = n.child("ior");
  c.allowOnly({"cauchy"});
  const JsonNode ab = c.child("cauchy");
  if (!ab.json().is_array() || ab.size() != 2) ab.fail(ab.what() + " must be [n_d, B]: the index at 587.6 nm and B in um^2");
  m.ior = ab.at(0).asNumber();
  m.cauchyB = ab.at(1).asNumber();
  if (!(m.ior >= 1e-3f && m.ior <= 100.0f)) ab.at(0).fail("n_d must be within [0.001, 100]");
  if (!(std::abs(m.cauchyB) <= 1.0f)) ab.at(1).fail("B must be within [-1, 1] um^2 (glass: about 0.004)");
  if (!(m.iorAt(380.0f) > 1e-3f && m.iorAt(830.0f) > 1e-3f)) ab.fail("the index must stay positive over 380-830 nm");
}

Material parseMaterial(const JsonNode& n, const std::string& name, const std::string& baseDir) {
  Material m;
  m.name = name;
  const std::string bsdf = n.has("bsdf") ? n.string("bsdf") : "blinn-phong";
  if (bsdf == "blinn-phong") {
    n.allowOnly({"ka", "kd", "ks", "shininess", "mirror", "transmission", "ior", "absorption", "emission", "texture",
                 "bsdf"});
    m.model = BsdfModel::BlinnPhong;
    m.ka = n.color("ka", Rgb(0.0f));
    m.kd = colorOrSpectrum(n, "kd", Rgb(0.0f), baseDir, m.kdSpectrum);
    m.ks = n.color("ks", Rgb(0.0f));
    m.shininess = n.number("shininess", 1.0f, 0.0f, 1e6f);
    m.mirror = n.color("mirror", Rgb(0.0f));
    m.transmission = n.color("transmission", Rgb(0.0f));
    parseIor(n, m, 1.0f);
    m.absorption = n.color("absorption", Rgb(0.0f));
    m.emission = colorOrSpectrum(n, "emission", Rgb(0.0f), baseDir, m.emissionSpectrum);
    m.texture = parseTexture(n, baseDir);
  } else if (bsdf == "lambert") {
    n.allowOnly({"bsdf", "ka", "kd", "emission", "texture"});
    m.model = BsdfModel::Lambert;
    m.ka = n.color("ka", Rgb(0.0f));
    m.kd = colorOrSpectrum(n, "kd", Rgb(0.0f), baseDir, m.kdSpectrum);
    m.emission = colorOrSpectrum(n, "emission", Rgb(0.0f), baseDir, m.emissionSpectrum);
    m.texture = parseTexture(n, baseDir);
  } else if (bsdf == "conductor") {
    n.allowOnly({"bsdf", "metal", "eta", "k", "roughness"});
    m.model = BsdfModel::Conductor;
    m.roughness = n.number("roughness", 0.0f, 0.0f, 1.0f);
    if (n.has("metal")) {
      if (n.has("eta") || n.has("k")) n.child("metal").fail("give either \"metal\" or \"eta\" and \"k\", not both");
      m.metal = n.string("metal");
      const std::optional<MetalIndex> metal = namedMetal(m.metal);
      if (!metal) n.child("metal").fail("unknown metal '" + m.metal + "' (allowed: " + joinNames(metalNames()) + ")");
      m.eta = metal->eta;
      m.k = metal->k;
      m.etaSpectrum = metal->etaSpectrum;
      m.kSpectrum = metal->kSpectrum;
    } else {
      if (!n.has("eta") || !n.has("k"))
        n.fail("a conductor needs \"metal\" (" + joinNames(metalNames()) + ") or both \"eta\" and \"k\"");
      m.eta = n.color("eta", Rgb(1.0f));
      m.k = n.color("k", Rgb(0.0f));
      if (minComponent(m.eta) <= 0.0f) n.child("eta").fail("eta must be > 0 in every channel");
    }
    conductorLocalLimit(m);
  } else if (bsdf == "dielectric" || bsdf == "rough-dielectric") {
    const bool rough = bsdf == "rough-dielectric";
    if (rough)
      n.allowOnly({"bsdf", "ior", "absorption", "transmission", "roughness"});
    else
      n.allowOnly({"bsdf", "ior", "absorption", "transmission"});
    m.model = rough ? BsdfModel::RoughDielectric : BsdfModel::Dielectric;
    m.roughness = rough ? n.number("roughness", 0.1f, 0.0f, 1.0f) : 0.0f;
    m.transmission = n.color("transmission", Rgb(1.0f));
    parseIor(n, m, 1.5f);
    m.absorption = n.color("absorption", Rgb(0.0f));
  } else {
    n.child("bsdf").fail("unknown bsdf '" + bsdf +
                         "' (allowed: blinn-phong, lambert, conductor, dielectric, rough-dielectric)");
  }
  return m;
}

// A point the scene places (eye, light, vertex) beyond the limits is overflow: say so at its key.
std::string overflowMessage(const std::string& what, float magnitude, float limit = kMaxSceneCoordinate) {
  std::ostringstream s;
  s << what << " reaches " << magnitude << " scene units: overflow (allowed: within +-" << limit
    << " units, where float arithmetic stays exact enough; scale the scene down)";
  return s.str();
}

Vec3 pointWithinLimits(const JsonNode& n, const std::string& key, float limit = kMaxSceneCoordinate) {
  const Vec3 p = n.vec3(key);
  if (!(largestMagnitude(p) <= limit)) n.child(key).fail(overflowMessage(n.child(key).what(), largestMagnitude(p), limit));
  return p;
}

Light parseLight(const JsonNode& n) {
  n.requireObject();
  const std::string type = n.string("type");
  Light l;
  if (type == "point") {
    n.allowOnly({"type", "position", "intensity"});
    l.type = Light::Type::Point;
    l.position = pointWithinLimits(n, "position");
  } else if (type == "directional") {
    n.allowOnly({"type", "direction", "intensity"});
    l.type = Light::Type::Directional;
    const Vec3 d = n.vec3("direction");
    if (glm::length(d) <= 0.0f) n.child("direction").fail("directional light direction must be non-zero");
    l.direction = glm::normalize(d);
  } else {
    n.child("type").fail("unknown light type '" + type +
                         "' (allowed: point, directional; area lights are emissive objects)");
  }
  l.intensity = n.color("intensity", Rgb(1.0f));
  return l;
}

// Appends triangles (object-space data transformed to world space).
class GeometryBuilder {
 public:
  explicit GeometryBuilder(Scene& scene) : scene_(scene) {}

  void addTriangles(uint32_t object, const TriangleMesh& mesh, const Transform& xf) {
    Geometry& g = scene_.geometry;
    const auto base = static_cast<uint32_t>(g.positions.size());
    for (const Vec3& p : mesh.positions) g.positions.push_back(xf.point(p));
    pendingNormals_.resize(g.positions.size() - mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i)
      pendingNormals_.push_back(mesh.normals.empty() ? Vec3(0.0f) : xf.dir(mesh.normals[i]));
    anyNormals_ |= !mesh.normals.empty();
    pendingUvs_.resize(g.positions.size() - mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i)
      pendingUvs_.push_back(mesh.uvs.empty() ? Vec2(0.0f) : mesh.uvs[i]);
    anyUvs_ |= !mesh.uvs.empty();
    for (const glm::uvec3& t : mesh.triangles) {
      // Zero-area triangles (repeated or collinear vertices) can neither be hit nor shaded: drop them.
      const Vec3 &a = g.positions[base + t.x], &b = g.positions[base + t.y], &c = g.positions[base + t.z];
      if (glm::length(glm::cross(b - a, c - a)) == 0.0f) continue;
      g.triangles.push_back(t + glm::uvec3(base));
      g.triangleObject.push_back(object);
    }
  }

  void addSphere(uint32_t object, const Sphere& s) {
    spheres_.push_back(s);
    sphereObjects_.push_back(object);
  }

  // Moves spheres behind the triangles and fixes each object's primitive range.
  void finish() {
    Geometry& g = scene_.geometry;
    if (anyNormals_) g.normals = std::move(pendingNormals_);
    if (anyUvs_) g.uvs = std::move(pendingUvs_);
    g.spheres = std::move(spheres_);
    g.sphereObject = std::move(sphereObjects_);
    for (SceneObject& o : scene_.objects) o.primCount = 0;
    std::vector<uint32_t> first(scene_.objects.size(), Hit::kNone);
    for (uint32_t p = 0; p < g.primitiveCount(); ++p) {
      const uint32_t o = g.objectOf(p);
      if (first[o] == Hit::kNone) first[o] = p;
      ++scene_.objects[o].primCount;
    }
    for (size_t o = 0; o < scene_.objects.size(); ++o)
      scene_.objects[o].firstPrim = first[o] == Hit::kNone ? 0 : first[o];
  }

 private:
  Scene& scene_;
  std::vector<Vec3> pendingNormals_;
  std::vector<Vec2> pendingUvs_;
  bool anyNormals_ = false, anyUvs_ = false;
  std::vector<Sphere> spheres_;
  std::vector<uint32_t> sphereObjects_;
};

std::vector<Vec3> parsePoints(const JsonNode& list, size_t minCount) {
  list.requireArray();
  if (list.size() < minCount)
    list.fail(list.what() + " needs at least " + std::to_string(minCount) + " points, got " +
              std::to_string(list.size()));
  std::vector<Vec3> pts;
  for (size_t i = 0; i < list.size(); ++i) pts.push_back(list.at(i).asVec3());
  return pts;
}

float polygonArea(const std::vector<Vec3>& p) {
  Vec3 sum(0.0f);
  for (size_t i = 1; i + 1 < p.size(); ++i) sum += glm::cross(p[i] - p[0], p[i + 1] - p[0]);
  return 0.5f * glm::length(sum);
}

TriangleMesh fan(const std::vector<Vec3>& p) {
  TriangleMesh m;
  m.positions = p;
  for (unsigned i = 1; i + 1 < p.size(); ++i) m.triangles.emplace_back(0u, i, i + 1);
  return m;
}

void parseObject(const JsonNode& n, Scene& scene, GeometryBuilder& builder,
                 const std::map<std::string, uint32_t>& materialIds, const std::string& baseDir) {
  n.requireObject();
  const std::string type = n.string("type");
  const auto object = static_cast<uint32_t>(scene.objects.size());
  SceneObject obj;
  obj.type = type;
  obj.name = n.has("name") ? n.string("name") : type + " " + std::to_string(object);
  const std::string mat = n.string("material");
  const auto it = materialIds.find(mat);
  if (it == materialIds.end()) {
    std::vector<std::string> names;
    for (const auto& [k, v] : materialIds) names.push_back(k);
    n.child("material").fail("unknown material '" + mat + "' (defined: " + joinNames(names) + ")");
  }
  obj.material = it->second;
  const Transform xf = parseTransform(n);

  if (type == "sphere") {
    n.allowOnly({"type", "name", "material", "transform", "center", "radius"});
    const Vec3 c = n.vec3("center");
    const JsonNode radius = n.child("radius");
    const float r = radius.asNumber();
    if (!(r > 0.0f)) radius.fail(radius.what() + " must be > 0, got " + radius.json().dump());
    float s = 1.0f;
    if (!xf.uniformScale(s)) n.child("transform").fail("spheres take only uniform scale");
    builder.addSphere(object, Sphere{xf.point(c), r * s});
  } else if (type == "quad" || type == "polygon") {
    n.allowOnly({"type", "name", "material", "transform", "vertices"});
    const JsonNode v = n.child("vertices");
    std::vector<Vec3> pts = parsePoints(v, type == "quad" ? 4 : 3);
    if (type == "quad" && pts.size() != 4) v.fail("a quad has exactly 4 vertices, got " + std::to_string(pts.size()));
    if (!(polygonArea(pts) > 0.0f)) v.fail(n.what() + " has zero area");
    TriangleMesh m = fan(pts);
    if (type == "quad") m.uvs = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
    builder.addTriangles(object, m, xf);
  } else if (type == "triangles") {
    n.allowOnly({"type", "name", "material", "transform", "positions", "indices", "normals", "uvs"});
    TriangleMesh m;
    m.positions = parsePoints(n.child("positions"), 3);
    const JsonNode idx = n.child("indices");
    idx.requireArray();
    for (size_t i = 0; i < idx.size(); ++i) {
      const JsonNode t = idx.at(i);
      if (!t.json().is_array() || t.size() != 3) t.fail(t.what() + " must be 3 vertex indices [i, j, k]");
      glm::uvec3 tri;
      for (int k = 0; k < 3; ++k) {
        const JsonNode e = t.at(static_cast<size_t>(k));
        if (!e.json().is_number_integer() || e.json().get<long long>() < 0 ||
            e.json().get<long long>() >= static_cast<long long>(m.positions.size()))
          e.fail(e.what() + " must be a vertex index in [0, " + std::to_string(m.positions.size() - 1) + "]");
        tri[k] = e.json().get<unsigned>();
      }
      m.triangles.push_back(tri);
    }
    if (n.has("normals")) {
      m.normals = parsePoints(n.child("normals"), m.positions.size());
      if (m.normals.size() != m.positions.size()) n.child("normals").fail("needs one normal per position");
    }
    if (n.has("uvs")) {
      const JsonNode uv = n.child("uvs");
      uv.requireArray();
      if (uv.size() != m.positions.size()) uv.fail("needs one uv per position");
      for (size_t i = 0; i < uv.size(); ++i) m.uvs.push_back(uv.at(i).asVec2());
    }
    builder.addTriangles(object, m, xf);
  } else if (type == "mesh") {
    n.allowOnly({"type", "name", "material", "transform", "file", "smooth"});
    const JsonNode f = n.child("file");
    const std::string file = (fs::path(baseDir) / n.string("file")).lexically_normal().string();
    TriangleMesh m;
    try {
      m = loadMeshFile(file, n.boolean("smooth", true));
    } catch (const UserError& e) {
      f.fail(e.what());
    }
    builder.addTriangles(object, m, xf);
  } else {
    n.child("type").fail("unknown object type '" + type + "' (allowed: sphere, quad, polygon, triangles, mesh)");
  }
  scene.objects.push_back(obj);
}

}  // namespace

Camera parseCamera(const JsonNode& n) {
  n.allowOnly({"eye", "target", "up", "fov_y_deg", "width", "height"});
  Camera c;
  c.eye = pointWithinLimits(n, "eye", kMaxCameraCoordinate);
  c.target = pointWithinLimits(n, "target", kMaxCameraCoordinate);
  c.up = n.vec3("up", Vec3(0, 1, 0));
  c.fovYDeg = n.number("fov_y_deg", 0.01f, 179.0f);
  c.width = n.integer("width", 512, 1, 16384);
  c.height = n.integer("height", 512, 1, 16384);
  const Vec3 view = c.target - c.eye;
  if (glm::length(view) <= 0.0f) n.child("target").fail("camera target equals the eye; they must differ");
  if (glm::length(c.up) <= 0.0f) n.child("up").fail("camera up must be non-zero");
  if (glm::length(glm::cross(glm::normalize(view), glm::normalize(c.up))) < 1e-6f)
    n.fail("camera up is parallel to the view direction (target - eye); choose another up");
  return c;
}

// "background": [r, g, b] (a constant sky), {"color": [r, g, b]} or {"image": "sky.hdr", "strength": 1,
// "rotation_deg": 0}; an object may say "lights_scene": false (a backdrop that lights nothing).
Environment parseBackground(const JsonNode& root, const std::string& baseDir) {
  if (!root.has("background")) return Environment(Rgb(0.0f));
  const JsonNode n = root.child("background");
  if (!n.json().is_object()) return Environment(root.color("background", Rgb(0.0f)));
  n.allowOnly({"color", "image", "strength", "rotation_deg", "lights_scene"});
  const bool lightsScene = n.boolean("lights_scene", true);
  if (n.has("color")) {
    if (n.has("image") || n.has("strength") || n.has("rotation_deg"))
      n.fail("background: give \"color\" or \"image\" (with strength, rotation_deg), not both");
    Environment sky(n.color("color", Rgb(0.0f)));
    sky.setLightsScene(lightsScene);
    return sky;
  }
  const JsonNode image = n.child("image");
  if (!image.json().is_string()) image.fail(image.what() + " must be a file name (an equirectangular .hdr or .pfm)");
  const std::string file = sceneRelativeFile(image, baseDir, "sky image");
  const float strength = n.number("strength", 1.0f, 0.0f, 1e6f);
  const float rotation = n.number("rotation_deg", 0.0f, -360.0f, 360.0f);
  auto sky = std::make_shared<Image>(loadImage(file));
  if (sky->width() < 2 || sky->height() < 1)
    image.fail("sky image " + file + " is too small (allowed: at least 2 x 1 pixels, 2:1 equirectangular)");
  Environment environment(std::move(sky), strength, rotation);
  environment.setLightsScene(lightsScene);
  return environment;
}

Scene parseJsonScene(const std::string& text, const std::string& file, const std::string& baseDir) {
  const JsonDocument doc(text, file);
  const JsonNode root(doc, doc.root(), "", "scene");
  root.allowOnly({"description", "source", "camera", "background", "ambient", "materials", "lights", "objects"});
  Scene scene;
  scene.path = file;
  scene.camera = parseCamera(root.child("camera"));
  scene.environment = parseBackground(root, baseDir);
  scene.background = scene.environment.average();
  scene.ambient = root.color("ambient", Rgb(0.0f));

  std::map<std::string, uint32_t> materialIds;
  const JsonNode mats = root.child("materials");
  mats.requireObject();
  for (auto it = mats.json().begin(); it != mats.json().end(); ++it) {
    materialIds[it.key()] = static_cast<uint32_t>(scene.materials.size());
    scene.materials.push_back(parseMaterial(mats.child(it.key()), it.key(), baseDir));
  }
  if (root.has("lights")) {
    const JsonNode lights = root.child("lights");
    lights.requireArray();
    for (size_t i = 0; i < lights.size(); ++i) scene.lights.push_back(parseLight(lights.at(i)));
  }
  const JsonNode objects = root.child("objects");
  objects.requireArray();
  GeometryBuilder builder(scene);
  for (size_t i = 0; i < objects.size(); ++i) parseObject(objects.at(i), scene, builder, materialIds, baseDir);
  builder.finish();
  const Geometry& g = scene.geometry;
  for (uint32_t p = 0; p < g.primitiveCount(); ++p) {
    const Bounds3 b = g.bounds(p);
    if (withinSceneLimits(b.min) && withinSceneLimits(b.max)) continue;
    const uint32_t o = g.objectOf(p);
    objects.at(o).fail(overflowMessage("object '" + scene.objects[o].name + "'",
                                       std::max(largestMagnitude(b.min), largestMagnitude(b.max))));
  }
  scene.finalize();
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    if (!scene.materials[o.material].emits()) continue;
    const bool hasArea = std::any_of(scene.areaLights.begin(), scene.areaLights.end(),
                                     [&](const AreaLight& l) { return l.object == i; });
    if (!hasArea) objects.at(i).fail("emissive object '" + o.name + "' has zero area: it cannot light anything");
  }
  return scene;
}

Scene loadScene(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throwUserError(path + ": " + (ec ? "cannot open scene file (" + ec.message() + ")" : "no such scene file"));
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".obj") return loadObjScene(path);
  if (ext != ".json") throwUserError(path + ": unknown scene format '" + ext + "' (allowed: .json, .obj)");
  const std::string text = readTextFile(path, "scene file");
  return parseJsonScene(text, path, fs::path(path).parent_path().string());
}

}  // namespace ll
