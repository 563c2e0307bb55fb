#include "patch_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "core/phase_progress.h"
#include "discontinuity_cuts.h"

namespace ll::a5 {

namespace {

using OmMesh = OpenMesh::TriMesh_ArrayKernelT<>;

OmMesh::Point toOm(const Vec3& v) { return {v.x, v.y, v.z}; }
Vec3 fromOm(const OmMesh::Point& p) { return {p[0], p[1], p[2]}; }

// One object's triangles as an OpenMesh mesh. Triangles OpenMesh refuses
// (non-manifold fans) are added with vertices of their own.
void addObjectTriangles(const Scene& scene, const SceneObject& object, int sphereSegments, OmMesh& mesh) {
  const Geometry& g = scene.geometry;
  std::map<uint32_t, OmMesh::VertexHandle> vertexOf;
  const auto handle = [&](uint32_t index) {
    auto it = vertexOf.find(index);
    if (it == vertexOf.end()) it = vertexOf.emplace(index, mesh.add_vertex(toOm(g.positions[index]))).first;
    return it->second;
  };
  const auto addTriangle = [&](OmMesh::VertexHandle a, OmMesh::VertexHandle b, OmMesh::VertexHandle c) {
    if (mesh.add_face(a, b, c).is_valid()) return;
    mesh.add_face(mesh.add_vertex(mesh.point(a)), mesh.add_vertex(mesh.point(b)), mesh.add_vertex(mesh.point(c)));
  };
  for (uint32_t prim = object.firstPrim; prim < object.firstPrim + object.primCount; ++prim) {
    if (g.isTriangle(prim)) {
      const glm::uvec3& t = g.triangles[prim];
      if (glm::length(glm::cross(g.positions[t.y] - g.positions[t.x], g.positions[t.z] - g.positions[t.x])) <= 0.0f)
        continue;  // degenerate: no area, no patch
      addTriangle(handle(t.x), handle(t.y), handle(t.z));
      continue;
    }
    // A sphere: a latitude-longitude grid with shared vertices, poles included.
    const Sphere& s = g.spheres[prim - g.triangleCount()];
    const int segments = std::max(sphereSegments, 6), rings = std::max(segments / 2, 3);
    std::vector<OmMesh::VertexHandle> grid;
    const OmMesh::VertexHandle south = mesh.add_vertex(toOm(s.center - Vec3(0, s.radius, 0)));
    const OmMesh::VertexHandle north = mesh.add_vertex(toOm(s.center + Vec3(0, s.radius, 0)));
    for (int j = 1; j < rings; ++j)
      for (int i = 0; i < segments; ++i) {
        const float theta = kPi * static_cast<float>(j) / static_cast<float>(rings) - kPi / 2;
        const float phi = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
        grid.push_back(mesh.add_vertex(
            toOm(s.center + s.radius * Vec3(std::cos(theta) * std::cos(phi), std::sin(theta),
                                            std::cos(theta) * std::sin(phi)))));
      }
    const auto at = [&](int i, int j) { return grid[static_cast<size_t>((j - 1) * segments + (i % segments))]; };
    for (int i = 0; i < segments; ++i) {  // outward winding (counter-clockwise seen from outside)
      addTriangle(south, at(i, 1), at(i + 1, 1));
      addTriangle(north, at(i + 1, rings - 1), at(i, rings - 1));
      for (int j = 1; j + 1 < rings; ++j) {
        addTriangle(at(i, j), at(i, j + 1), at(i + 1, j + 1));
        addTriangle(at(i, j), at(i + 1, j + 1), at(i + 1, j));
      }
    }
  }
}

// Splits every edge longer than maxEdge at its midpoint, longest first, until none is.
void splitLongEdges(OmMesh& mesh, float maxEdge) {
  for (int round = 0; round < 64; ++round) {
    std::vector<std::pair<float, OmMesh::EdgeHandle>> longEdges;
    for (const auto e : mesh.edges()) {
      const float length = mesh.calc_edge_length(e);
      if (length > maxEdge) longEdges.emplace_back(length, e);
    }
    if (longEdges.empty()) return;
    std::sort(longEdges.begin(), longEdges.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (const auto& [length, e] : longEdges) {
      if (mesh.calc_edge_length(e) <= maxEdge) continue;  // (lengths do not change, but keep it safe)
      const auto h = mesh.halfedge_handle(e, 0);
      const OmMesh::Point mid = 0.5f * (mesh.point(mesh.from_vertex_handle(h)) + mesh.point(mesh.to_vertex_handle(h)));
      mesh.split(e, mid);
    }
  }
}

}  // namespace

void PatchMesh::buildViews() {
  PatchMesh& out = *this;
  Geometry& g = out.geometry;
  g = Geometry{};
  g.positions = out.positions;
  out.vertexPatches.assign(out.positions.size(), {});
  out.primPatch.clear();
  for (uint32_t i = 0; i < out.patches.size(); ++i) {
    const Patch& p = out.patches[i];
    g.triangles.push_back(p.vertices);
    g.triangleObject.push_back(p.object);
    out.primPatch.push_back(i);
    if (p.corners() == 4) {
      g.triangles.emplace_back(p.vertices.x, p.vertices.z, p.fourth);
      g.triangleObject.push_back(p.object);
      out.primPatch.push_back(i);
    }
    for (int k = 0; k < p.corners(); ++k) out.vertexPatches[p.corner(k)].push_back(i);
  }
}

int PatchMesh::cornerPositions(uint32_t i, Vec3 out[4]) const {
  const Patch& p = patches[i];
  for (int k = 0; k < p.corners(); ++k) out[k] = positions[p.corner(k)];
  return p.corners();
}

Vec3 pointOnPolygon(const Vec3* c, int count, Vec2 u) {
  // Triangle (0, 1, 2), or (0, 2, 3) with the probability of its share of the area; u.x reused within it.
  const auto onTriangle = [](const Vec3& a, const Vec3& b, const Vec3& d, Vec2 w) {
    const float s = std::sqrt(w.x);
    return (1.0f - s) * a + s * (1.0f - w.y) * b + s * w.y * d;
  };
  if (count == 3) return onTriangle(c[0], c[1], c[2], u);
  const float a0 = glm::length(glm::cross(c[1] - c[0], c[2] - c[0])), a1 = glm::length(glm::cross(c[2] - c[0], c[3] - c[0]));
  const float first = a0 / (a0 + a1);
  if (u.x < first) return onTriangle(c[0], c[1], c[2], Vec2(u.x / first, u.y));
  return onTriangle(c[0], c[2], c[3], Vec2(std::min((u.x - first) / (1.0f - first), 1.0f - 1e-7f), u.y));
}

float PatchMesh::totalArea() const {
  float a = 0.0f;
  for (const Patch& p : patches) a += p.area;
  return a;
}

namespace {

// Where object o was cut (its patches from firstPatch on, its vertices from
// firstVertex on): a corner on an outline segment (not on the rest of its
// line: the radiosity is continuous there), shared by patches on both sides
// of it, gets one copy per side (same position: the mesh stays crack-free
// and its edges conforming), so interpolated corner radiosities do not blend
// across the jump (the dark patches hidden under the lamp gave it a halo).
void separateAlongCuts(PatchMesh& out, uint32_t firstPatch, uint32_t firstVertex, const std::vector<CutLine>& lines,
                       const Vec3& normal) {
  if (lines.empty()) return;
  // Bit l: patch centre c is on the positive side of line l, where corner x lies on segment l.
  const auto side = [&](const Vec3& x, const Vec3& c) {
    uint64_t code = 0;
    for (size_t l = 0; l < lines.size(); ++l) {
      const CutLine& line = lines[l];
      const Vec3 across = glm::normalize(glm::cross(normal, line.direction)), off = x - line.point;
      const float along = glm::dot(off, line.direction), tolerance = 1e-4f * line.length;
      if (std::abs(glm::dot(across, off)) > tolerance || along < -tolerance || along > line.length + tolerance) continue;
      if (glm::dot(across, c - line.point) > 0.0f) code |= uint64_t{1} << l;
      code |= uint64_t{1} << (32 + l);  // (on segment l at all: both sides differ from "on none")
    }
    return code;
  };
  std::map<std::pair<uint32_t, uint64_t>, uint32_t> copyOf;  // (vertex, side) -> its index for that side
  std::vector<uint64_t> firstSide(out.positions.size() - firstVertex, ~uint64_t{0});
  for (size_t i = firstPatch; i < out.patches.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      uint32_t& v = out.patches[i].vertices[k];
      const uint64_t here = side(out.positions[v], out.patches[i].centre);
      uint64_t& owner = firstSide[v - firstVertex];
      if (owner == ~uint64_t{0}) owner = here;
      if (owner == here) continue;
      auto it = copyOf.find({v, here});
      if (it == copyOf.end()) {
        it = copyOf.emplace(std::make_pair(v, here), static_cast<uint32_t>(out.positions.size())).first;
        out.positions.push_back(out.positions[v]);
      }
      v = it->second;
    }
}

// Emission and reflectance of a patch of material m.
void setMaterial(const Material& m, Patch& p) {
  p.emission = kPi * m.emission;
  p.reflectance = glm::clamp(m.kd, Rgb(0.0f), Rgb(1.0f));
  if (m.texture.kind != Texture::Kind::None) p.reflectance = glm::clamp(m.diffuse(Vec2(0.5f)), Rgb(0.0f), Rgb(1.0f));
}

// Appends object o's faces of `mesh` as patches (and its vertices), separated along `lines`.
void appendObject(const Scene& scene, uint32_t o, const OmMesh& mesh, PatchMesh& out,
                  const std::vector<CutLine>& lines = {}) {
  const Material& m = scene.materials[scene.objects[o].material];
  const auto base = static_cast<uint32_t>(out.positions.size());
  const auto firstPatch = static_cast<uint32_t>(out.patches.size());
  for (const auto v : mesh.vertices()) out.positions.push_back(fromOm(mesh.point(v)));
  for (const auto f : mesh.faces()) {
    glm::uvec3 idx;
    int k = 0;
    for (const auto v : mesh.fv_range(f)) idx[k++] = base + static_cast<uint32_t>(v.idx());
    Patch p;
    p.object = o;
    p.vertices = idx;
    const Vec3 a = out.positions[idx.x], b = out.positions[idx.y], c = out.positions[idx.z];
    const Vec3 cross = glm::cross(b - a, c - a);
    p.area = 0.5f * glm::length(cross);
    if (!(p.area > 0.0f)) continue;
    p.normal = cross / (2.0f * p.area);
    p.centre = (a + b + c) / 3.0f;
    setMaterial(m, p);
    out.patches.push_back(p);
  }
  if (!lines.empty() && out.patches.size() > firstPatch)
    separateAlongCuts(out, firstPatch, base, lines, out.patches[firstPatch].normal);
}

// The corners (c0, c1, c2, c3) of object o if it is one planar, convex quad
// (as the scene loader makes it: triangles (0, 1, 2) and (0, 2, 3)).
bool planarQuad(const Scene& scene, const SceneObject& object, Vec3 c[4]) {
  const Geometry& g = scene.geometry;
  if (object.type != "quad" || object.primCount != 2 || !g.isTriangle(object.firstPrim)) return false;
  const glm::uvec3 t0 = g.triangles[object.firstPrim], t1 = g.triangles[object.firstPrim + 1];
  if (t1.x != t0.x || t1.y != t0.z) return false;
  c[0] = g.positions[t0.x];
  c[1] = g.positions[t0.y];
  c[2] = g.positions[t0.z];
  c[3] = g.positions[t1.z];
  const Vec3 n0 = glm::cross(c[1] - c[0], c[2] - c[0]), n1 = glm::cross(c[2] - c[0], c[3] - c[0]);
  const float l0 = glm::length(n0), l1 = glm::length(n1);
  if (!(l0 > 0.0f && l1 > 0.0f)) return false;
  // Convex (the other diagonal splits it into two front-facing triangles too) and planar.
  const Vec3 n2 = glm::cross(c[2] - c[1], c[3] - c[1]), n3 = glm::cross(c[3] - c[1], c[0] - c[1]);
  const Vec3 n = n0 / l0;
  return glm::dot(n0 / l0, n1 / l1) > 1.0f - 1e-6f && glm::dot(n, n2) > 0.0f && glm::dot(n, n3) > 0.0f;
}

// Object o, a planar convex quad with corners c, as a grid of quad patches no
// longer than maxEdge along either side (bilinear in the corners: planar).
void appendQuadGrid(const Scene& scene, uint32_t o, const Vec3 c[4], float maxEdge, PatchMesh& out) {
  const Material& m = scene.materials[scene.objects[o].material];
  const auto cells = [&](float length) { return std::max(1, static_cast<int>(std::ceil(length / maxEdge))); };
  const int nu = cells(std::max(glm::length(c[1] - c[0]), glm::length(c[2] - c[3])));
  const int nv = cells(std::max(glm::length(c[3] - c[0]), glm::length(c[2] - c[1])));
  const auto base = static_cast<uint32_t>(out.positions.size());
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(nu), v = static_cast<float>(j) / static_cast<float>(nv);
      out.positions.push_back((1 - u) * (1 - v) * c[0] + u * (1 - v) * c[1] + u * v * c[2] + (1 - u) * v * c[3]);
    }
  const auto at = [&](int i, int j) { return base + static_cast<uint32_t>(j * (nu + 1) + i); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      Patch p;
      p.object = o;
      p.vertices = glm::uvec3(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      p.fourth = at(i, j + 1);
      const Vec3 a = out.positions[p.vertices.x], b = out.positions[p.vertices.y], d = out.positions[p.vertices.z],
                 e = out.positions[p.fourth];
      const Vec3 n0 = glm::cross(b - a, d - a), n1 = glm::cross(d - a, e - a);
      const float a0 = 0.5f * glm::length(n0), a1 = 0.5f * glm::length(n1);
      p.area = a0 + a1;
      if (!(p.area > 0.0f)) continue;
      p.normal = glm::normalize(n0 + n1);
      p.centre = (a0 * (a + b + d) + a1 * (a + d + e)) / (3.0f * p.area);  // the area centroid
      setMaterial(m, p);
      out.patches.push_back(p);
    }
}


// Object o's triangles cut along `lines` (discontinuity_cuts.h), into `mesh`
// with corners shared by position (the cuts made them as floats).
void addCutTriangles(const Scene& scene, const SceneObject& object, const std::vector<CutLine>& lines, float snap,
                     OmMesh& mesh) {
  const Geometry& g = scene.geometry;
  std::vector<Triangle3> triangles;
  for (uint32_t prim = object.firstPrim; prim < object.firstPrim + object.primCount; ++prim) {
    const glm::uvec3& t = g.triangles[prim];
    if (glm::length(glm::cross(g.positions[t.y] - g.positions[t.x], g.positions[t.z] - g.positions[t.x])) > 0.0f)
      triangles.push_back({g.positions[t.x], g.positions[t.y], g.positions[t.z]});
  }
  std::map<std::tuple<float, float, float>, OmMesh::VertexHandle> vertexAt;
  const auto handle = [&](const Vec3& v) {
    auto it = vertexAt.find({v.x, v.y, v.z});
    if (it == vertexAt.end()) it = vertexAt.emplace(std::make_tuple(v.x, v.y, v.z), mesh.add_vertex(toOm(v))).first;
    return it->second;
  };
  for (const Triangle3& t : cutTriangles(triangles, lines, snap)) {
    const OmMesh::VertexHandle a = handle(t[0]), b = handle(t[1]), c = handle(t[2]);
    if (!mesh.add_face(a, b, c).is_valid())
      mesh.add_face(mesh.add_vertex(mesh.point(a)), mesh.add_vertex(mesh.point(b)), mesh.add_vertex(mesh.point(c)));
  }
}

}  // namespace

PatchMesh buildPatchMesh(const Scene& scene, float maxEdge, int sphereSegments, bool cutAlongContacts,
                         bool quadPatches) {
  PatchMesh out;
  const float diagonal = scene.geometry.sceneBounds().diagonal();
  for (uint32_t o = 0; o < scene.objects.size(); ++o) {
    // Object by object (a pane's newer request cancels here: the report throws).
    reportPhase("patch mesh", static_cast<double>(o) / static_cast<double>(scene.objects.size()));
    OmMesh mesh;
    const std::vector<CutLine> lines =
        cutAlongContacts ? contactLines(scene, o, kContactTolerance * diagonal) : std::vector<CutLine>{};
    Vec3 corners[4];
    if (quadPatches && lines.empty() && planarQuad(scene, scene.objects[o], corners)) {
      appendQuadGrid(scene, o, corners, maxEdge, out);
      out.cuts.emplace_back();
      continue;
    }
    if (lines.empty())
      addObjectTriangles(scene, scene.objects[o], sphereSegments, mesh);
    else
      addCutTriangles(scene, scene.objects[o], lines, 1e-5f * diagonal, mesh);
    splitLongEdges(mesh, maxEdge);
    appendObject(scene, o, mesh, out, lines);
    out.cuts.push_back(lines);
  }
  out.buildViews();
  return out;
}

PatchMesh refinePatchMesh(const Scene& scene, const PatchMesh& mesh, const std::vector<uint8_t>& split) {
  PatchMesh out;
  for (uint32_t o = 0; o < scene.objects.size(); ++o) {
    reportPhase("patch mesh", static_cast<double>(o) / static_cast<double>(scene.objects.size()));
    // The object's patches back into an OpenMesh mesh (they share their vertices).
    OmMesh m;
    std::map<std::tuple<float, float, float>, OmMesh::VertexHandle> vertexOf;  // by position: copies along cuts weld
    std::vector<std::pair<OmMesh::FaceHandle, bool>> faces;
    for (uint32_t i = 0; i < mesh.patches.size(); ++i) {
      const Patch& p = mesh.patches[i];
      if (p.object != o) continue;
      OmMesh::VertexHandle h[4];
      for (int k = 0; k < p.corners(); ++k) {
        const Vec3& x = mesh.positions[p.corner(k)];
        auto it = vertexOf.find({x.x, x.y, x.z});
        if (it == vertexOf.end()) it = vertexOf.emplace(std::make_tuple(x.x, x.y, x.z), m.add_vertex(toOm(x))).first;
        h[k] = it->second;
      }
      // A quad patch goes back as its two triangles.
      const auto addFace = [&](OmMesh::VertexHandle a, OmMesh::VertexHandle b, OmMesh::VertexHandle c) {
        OmMesh::FaceHandle f = m.add_face(a, b, c);
        if (!f.is_valid()) f = m.add_face(m.add_vertex(m.point(a)), m.add_vertex(m.point(b)), m.add_vertex(m.point(c)));
        faces.emplace_back(f, split[i] != 0);
      };
      addFace(h[0], h[1], h[2]);
      if (p.corners() == 4) addFace(h[0], h[2], h[3]);
    }
    // The longest edge of every marked patch, each once; splitting it splits both triangles on it.
    std::vector<OmMesh::EdgeHandle> edges;
    for (const auto& [f, marked] : faces) {
      if (!marked || !f.is_valid()) continue;
      OmMesh::EdgeHandle longest;
      float length = -1.0f;
      for (const auto e : m.fe_range(f))
        if (m.calc_edge_length(e) > length) {
          length = m.calc_edge_length(e);
          longest = e;
        }
      if (longest.is_valid()) edges.push_back(longest);
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for (const auto e : edges) {
      const auto h = m.halfedge_handle(e, 0);
      m.split(e, 0.5f * (m.point(m.from_vertex_handle(h)) + m.point(m.to_vertex_handle(h))));
    }
    const std::vector<CutLine> lines = o < mesh.cuts.size() ? mesh.cuts[o] : std::vector<CutLine>{};
    appendObject(scene, o, m, out, lines);
    out.cuts.push_back(lines);
  }
  out.buildViews();
  return out;
}

}  // namespace ll::a5
