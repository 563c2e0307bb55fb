// The scene as small flat diffuse patches for radiosity (framework code):
// every object's triangles (spheres tessellated first) are split with
// OpenMesh at the midpoints of their longest edges until no edge is longer
// than `maxEdge`. Splitting an edge splits both triangles on it, so the mesh
// stays conforming (no T-junctions) and vertex radiosities interpolate
// without cracks. Patch ids are stable: objects in scene order, each
// object's faces in OpenMesh's order.
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"
#include "discontinuity_cuts.h"
#include "scene/geometry.h"
#include "scene/scene.h"

namespace ll::a5 {

struct Patch {
  uint32_t object = 0;   // the scene object it belongs to
  glm::uvec3 vertices;   // indices into PatchMesh::positions (counter-clockwise seen from the front)
  Vec3 centre{0.0f};     // centroid, world space
  Vec3 normal{0.0f};     // unit, the front side (the winding's)
  float area = 0.0f;     // scene units^2
  Rgb emission{0.0f};    // E = pi * Le: emitted radiosity (front side), W/m^2 in scene units
  Rgb reflectance{0.0f}; // rho = the material's kd at the centre (diffuse albedo)
};

struct PatchMesh {
  std::vector<Vec3> positions;  // shared by the patches of one object
  std::vector<Patch> patches;
  // The patches as a Geometry (one triangle per patch, primitive id = patch
  // id), for accelerators: visibility rays and display.
  Geometry geometry;
  // Per vertex: the patches around it (for interpolated vertex radiosities).
  // A corner on a discontinuity line has one vertex per side (same position).
  std::vector<std::vector<uint32_t>> vertexPatches;
  std::vector<std::vector<CutLine>> cuts;  // per object: the lines it was cut along (discontinuity_cuts.h)
  float totalArea() const;
};

// Meshes `scene` into patches no longer than maxEdge (scene units) along any
// edge; spheres become `sphereSegments` x segments/2 quads first. With
// cutAlongContacts, planar objects are first cut along the outlines of the
// planar objects lying on them, within kContactTolerance of the scene's
// diagonal (discontinuity_cuts.h: the lamp's outline on the ceiling, the
// blocks' footprints on the floor). Precondition: maxEdge > 0.
constexpr float kContactTolerance = 1e-3f;
PatchMesh buildPatchMesh(const Scene& scene, float maxEdge, int sphereSegments = 24, bool cutAlongContacts = false);

// Adaptive refinement: splits the longest edge of every patch i with
// split[i] != 0 (and so the patch across that edge: the mesh stays
// conforming); everything else is kept. Patch ids are renumbered.
PatchMesh refinePatchMesh(const Scene& scene, const PatchMesh& mesh, const std::vector<uint8_t>& split);

}  // namespace ll::a5
