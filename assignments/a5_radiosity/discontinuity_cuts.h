// Discontinuity meshing, the part that needs no visibility (after Heckbert
// 1992, "Discontinuity meshing for radiosity", and Lischinski, Tampieri and
// Greenberg 1992): radiosity jumps along the outline of anything lying on a
// surface -- a lamp just below the ceiling, a block standing on the floor.
// A patch straddling such a line averages both sides (the dark halo beside
// the Cornell box's lamp, the smeared contact shadow under a block); cut
// along the line first, every patch lies on one side of it.
//
// A planar object is cut along the full lines through the boundary edges of
// other planar objects that lie in its plane (within `tolerance`, scene
// units) and over it. Cutting every triangle of the object along the same
// full lines keeps its mesh conforming (no T-vertices): a line crosses a
// shared edge at one point, computed the same way from both sides.
#pragma once

#include <array>
#include <vector>

#include "core/math.h"
#include "scene/scene.h"

namespace ll::a5 {

struct CutLine {
  Vec3 point{0.0f};      // on the line, in the object's plane: the outline segment's start
  Vec3 direction{0.0f};  // unit, in the object's plane
  float length = 0.0f;   // of the outline segment (scene units); the cut runs along the whole line
};

using Triangle3 = std::array<Vec3, 3>;

// The lines along which object `o` should be cut; empty when `o` is not
// planar (a sphere, a curved mesh) or nothing lies on it. At most
// kMaxCutLines (the nearest-to-centre first are kept: a mesh lying on a
// floor must not shred it).
constexpr size_t kMaxCutLines = 32;
std::vector<CutLine> contactLines(const Scene& scene, uint32_t o, float tolerance);

// `triangles` cut along every line (a line closer than `snap` to a corner
// passes through it). Triangles keep their winding.
std::vector<Triangle3> cutTriangles(std::vector<Triangle3> triangles, const std::vector<CutLine>& lines, float snap);

}  // namespace ll::a5
