#include "scene/mesh_file.h"

#include <algorithm>
#include <filesystem>

// OpenMesh wants its IO header before the mesh type.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include "core/error.h"
#include "core/files.h"

namespace ll {

namespace {
using OmMesh = OpenMesh::TriMesh_ArrayKernelT<>;
}

const std::vector<std::string>& meshExtensions() {
  static const std::vector<std::string> kExtensions = {".obj", ".ply", ".off", ".stl"};
  return kExtensions;
}

TriangleMesh loadMeshFile(const std::string& path, bool smoothNormals) {
  namespace fs = std::filesystem;
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  const auto& allowed = meshExtensions();
  if (std::find(allowed.begin(), allowed.end(), ext) == allowed.end())
    throwUserError(path + ": unknown mesh format '" + ext + "' (allowed: " + joinNames(allowed) + ")");
  // The error_code overloads: a name too long for the system is a message, not a filesystem_error.
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    if (ec) throwUserError(path + ": cannot open mesh file (" + ec.message() + ")");
    const fs::path absolute = fs::absolute(path, ec);
    throwUserError("mesh file not found: " + (ec ? path : absolute.lexically_normal().string()));
  }
  checkInputFile(path, "mesh file", kMaxMeshFileBytes);

  OmMesh mesh;
  mesh.request_vertex_normals();
  mesh.request_vertex_texcoords2D();
  OpenMesh::IO::Options options;
  options += OpenMesh::IO::Options::VertexNormal;
  options += OpenMesh::IO::Options::VertexTexCoord;
  // OpenMesh reports problems on its own stream (stderr); ours is the one line of the UserError below.
  omerr().disable();
  omlog().disable();
  if (!OpenMesh::IO::read_mesh(mesh, path, options))
    throwUserError(path + ": OpenMesh could not read this mesh (is it a valid " + ext + " file?)");
  if (mesh.n_faces() == 0) throwUserError(path + ": the mesh has no faces");

  TriangleMesh out;
  out.positions.reserve(mesh.n_vertices());
  for (const auto& vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    const Vec3 v(p[0], p[1], p[2]);
    if (!isFinite(v))
      throwUserError(path + ": vertex " + std::to_string(vh.idx()) + " has a non-finite coordinate");
    out.positions.push_back(v);
  }
  if (smoothNormals) {
    if (!options.check(OpenMesh::IO::Options::VertexNormal)) {
      mesh.request_face_normals();
      mesh.update_normals();
    }
    for (const auto& vh : mesh.vertices()) {
      const auto& n = mesh.normal(vh);
      Vec3 v(n[0], n[1], n[2]);
      const float len = glm::length(v);
      out.normals.push_back(len > 0.0f && std::isfinite(len) ? v / len : Vec3(0.0f));
    }
  }
  if (options.check(OpenMesh::IO::Options::VertexTexCoord))
    for (const auto& vh : mesh.vertices()) {
      const auto& t = mesh.texcoord2D(vh);
      out.uvs.emplace_back(t[0], t[1]);
    }
  for (const auto& fh : mesh.faces()) {
    glm::uvec3 tri;
    int i = 0;
    for (const auto& vh : mesh.fv_range(fh)) {
      if (i < 3) tri[i] = static_cast<unsigned>(vh.idx());
      ++i;
    }
    if (i == 3) out.triangles.push_back(tri);
  }
  return out;
}

}  // namespace ll
