// The scene as small flat diffuse patches for radiosity (framework code):
// every object's triangles (spheres tessellated first) are split with
// OpenMesh at the midpoints of their longest edges until no edge is longer
// than `maxEdge`. Splitting an edge splits both triangles on it, so the mesh
// stays conforming (no T-junctions) and vertex radiosities interpolate
// without cracks. A planar quad object (not cut, see below) becomes a grid
// of quad patches instead, so a cube can be one patch per face and closed
// forms for rectangles can be checked like for like. Patch ids are stable:
// objects in scene order, each object's faces in OpenMesh's (or the grid's)
// order.
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"
#include "discontinuity_cuts.h"
#include "scene/geometry.h"
#include "scene/scene.h"

namespace ll::a5 {

constexpr uint32_t kNoCorner = ~0u;

struct Patch {
  uint32_t object = 0;   // the scene object it belongs to
  // Indices into PatchMesh::positions, counter-clockwise seen from the front:
  // a triangle's corners, or a quad's first three and `fourth` (a planar,
  // convex quad: triangles (0, 1, 2) and (0, 2, 3)).
  glm::uvec3 vertices;
  uint32_t fourth = kNoCorner;
  int corners() const { return fourth == kNoCorner ? 3 : 4; }
  uint32_t corner(int k) const { return k < 3 ? vertices[k] : fourth; }
  Vec3 centre{0.0f};     // centroid, world space
  Vec3 normal{0.0f};     // unit, the front side (the winding's)
  float area = 0.0f;     // scene units^2
  Rgb emission{0.0f};    // E = pi * Le: emitted radiosity (front side), W/m^2 in scene units
  Rgb reflectance{0.0f}; // rho = the material's kd at the centre (diffuse albedo)
};

struct PatchMesh {
  std::vector<Vec3> positions;  // shared by the patches of one object
  std::vector<Patch> patches;
  // The patches as a Geometry (one triangle per triangle patch, two per quad
  // patch), for accelerators: visibility rays and display; primPatch maps a
  // primitive id back to its patch.
  Geometry geometry;
  std::vector<uint32_t> primPatch;
  // Per vertex: the patches around it (for interpolated vertex radiosities).
  // A corner on a discontinuity line has one vertex per side (same position).
  std::vector<std::vector<uint32_t>> vertexPatches;
  std::vector<std::vector<CutLine>> cuts;  // per object: the lines it was cut along (discontinuity_cuts.h)
  float totalArea() const;
  // Fills geometry, primPatch and vertexPatches from positions and patches.
  void buildViews();
  // Patch i's corner positions into `out`; returns their count (3 or 4).
  int cornerPositions(uint32_t i, Vec3 out[4]) const;
};

// A point on a convex polygon of 3 or 4 corners, uniform in area, for u uniform in [0, 1)^2.
Vec3 pointOnPolygon(const Vec3* corners, int count, Vec2 u);

// Meshes `scene` into patches no longer than maxEdge (scene units) along any
// edge; spheres become `sphereSegments` x segments/2 quads first. With
// cutAlongContacts, planar objects are first cut along the outlines of the
// planar objects lying on them, within kContactTolerance of the scene's
// diagonal (discontinuity_cuts.h: the lamp's outline on the ceiling, the
// blocks' footprints on the floor). Precondition: maxEdge > 0.
// With quadPatches, planar convex quad objects that are not cut become grids
// of quad patches (at most maxEdge along each side).
constexpr float kContactTolerance = 1e-3f;
PatchMesh buildPatchMesh(const Scene& scene, float maxEdge, int sphereSegments = 24, bool cutAlongContacts = false,
                         bool quadPatches = false);

// Adaptive refinement: splits the longest edge of every patch i with
// split[i] != 0 (and so the patch across that edge: the mesh stays
// conforming); everything else is kept (quad patches become their two
// triangles). Patch ids are renumbered.
PatchMesh refinePatchMesh(const Scene& scene, const PatchMesh& mesh, const std::vector<uint8_t>& split);

}  // namespace ll::a5
