// Triangle meshes from OBJ, PLY, OFF and STL files, read through OpenMesh.
#pragma once

#include <string>
#include <vector>

#include "core/math.h"

namespace ll {

struct TriangleMesh {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // per vertex, unit; empty if not requested
  std::vector<Vec2> uvs;      // per vertex; empty if the file has none
  std::vector<glm::uvec3> triangles;
};

// Reads `path` (polygons are triangulated). With smoothNormals, vertex normals
// come from the file or are computed from the faces. Throws UserError naming
// the path tried on a missing, unreadable, empty or non-finite mesh.
TriangleMesh loadMeshFile(const std::string& path, bool smoothNormals);

// The extensions loadMeshFile accepts, lower case with the dot.
const std::vector<std::string>& meshExtensions();

}  // namespace ll
