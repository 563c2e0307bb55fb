// Discontinuity meshing (discontinuity_cuts.h): planar surfaces are cut along
// the outlines of what lies on them. The mesh stays conforming (every inner
// edge is shared by exactly two patches: no T-vertices), no patch straddles
// an outline, and corner radiosities do not blend across it (the Cornell
// box's ceiling had a dark halo beside the lamp: its corners averaged the
// dark patches hidden under it).
#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "patch_mesh.h"
#include "radiosity_scene.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

// A unit floor with a 0.2 x 0.3 "lamp" 1e-4 above it, facing down (its outline is not parallel to the floor's grid).
Scene floorWithLamp() {
  return parseJsonScene(R"({"camera": {"eye": [0.5, 2, 2], "target": [0.5, 0, 0.5], "up": [0, 1, 0], "fov_y_deg": 40, "width": 8, "height": 8},
    "materials": {"white": {"kd": [0.5, 0.5, 0.5]}, "lamp": {"kd": [0.5, 0.5, 0.5], "emission": [1, 1, 1]}},
    "objects": [
      {"name": "floor", "type": "quad", "material": "white", "vertices": [[0, 0, 0], [0, 0, 1], [1, 0, 1], [1, 0, 0]]},
      {"name": "lamp", "type": "quad", "material": "lamp", "vertices": [[0.33, 0.0001, 0.41], [0.53, 0.0001, 0.41], [0.53, 0.0001, 0.71], [0.33, 0.0001, 0.71]]}]})",
                        "floor_with_lamp.json", ".");
}

using Point = std::tuple<float, float, float>;
Point at(const Vec3& v) { return {v.x, v.y, v.z}; }

TEST(DiscontinuityMeshing, TheFloorIsCutAlongTheLampOutlineAndStaysConforming) {
  const Scene scene = floorWithLamp();
  const a5::PatchMesh mesh = a5::buildPatchMesh(scene, 0.1f, 24, true);
  ASSERT_EQ(mesh.cuts.size(), 2u);
  EXPECT_EQ(mesh.cuts[0].size(), 4u);  // the lamp's four edges, on the floor
  EXPECT_TRUE(mesh.cuts[1].empty());   // the floor's outline is not over the lamp
  // Edges by their end positions: an inner edge twice (both ways), the outline once.
  std::map<std::pair<Point, Point>, int> uses;
  double area = 0.0, outline = 0.0;
  for (const a5::Patch& p : mesh.patches) {
    if (p.object != 0) continue;
    area += static_cast<double>(p.area);
    for (int k = 0; k < 3; ++k) {
      Point a = at(mesh.positions[p.vertices[k]]), b = at(mesh.positions[p.vertices[(k + 1) % 3]]);
      if (b < a) std::swap(a, b);
      ++uses[{a, b}];
    }
  }
  for (const auto& [edge, n] : uses) {
    ASSERT_LE(n, 2);
    if (n == 1)
      outline += std::hypot(static_cast<double>(std::get<0>(edge.first) - std::get<0>(edge.second)),
                            static_cast<double>(std::get<2>(edge.first) - std::get<2>(edge.second)));
  }
  EXPECT_NEAR(area, 1.0, 1e-5);
  EXPECT_NEAR(outline, 4.0, 1e-5);  // once-used edges make up the floor's outline only: no T-vertex inside
  // No floor patch straddles the lamp's footprint: all corners inside it (or on it), or all outside (or on it).
  const auto inside = [](const Vec3& v) { return v.x > 0.33f + 1e-6f && v.x < 0.53f - 1e-6f && v.z > 0.41f + 1e-6f && v.z < 0.71f - 1e-6f; };
  const auto outside = [](const Vec3& v) { return v.x < 0.33f - 1e-6f || v.x > 0.53f + 1e-6f || v.z < 0.41f - 1e-6f || v.z > 0.71f + 1e-6f; };
  int under = 0;
  for (const a5::Patch& p : mesh.patches) {
    if (p.object != 0) continue;
    bool in = false, out = false;
    for (int k = 0; k < 3; ++k) {
      in = in || inside(mesh.positions[p.vertices[k]]);
      out = out || outside(mesh.positions[p.vertices[k]]);
    }
    EXPECT_FALSE(in && out) << "a patch straddles the lamp's outline at " << p.centre.x << ", " << p.centre.z;
    under += inside(p.centre) ? 1 : 0;
  }
  EXPECT_GT(under, 0);
  // Without the cut, patches straddle it.
  const a5::PatchMesh plain = a5::buildPatchMesh(scene, 0.1f, 24, false);
  int straddling = 0;
  for (const a5::Patch& p : plain.patches) {
    bool in = false, out = false;
    for (int k = 0; k < 3; ++k) {
      in = in || inside(plain.positions[p.vertices[k]]);
      out = out || outside(plain.positions[p.vertices[k]]);
    }
    straddling += p.object == 0 && in && out ? 1 : 0;
  }
  EXPECT_GT(straddling, 0);
}

// The Cornell box's ceiling next to the lamp: the corners on the lamp's
// outline, seen from the ceiling patches outside it, are as bright as those
// patches (they averaged in the dark patches under the lamp: about half).
TEST(DiscontinuityMeshing, TheCeilingBesideTheLampHasNoDarkHalo) {
  const Scene scene = loadScene(std::string(LIGHTLAB_DATA_DIR) + "/scenes/cornell_box.json");
  uint32_t ceiling = 0;
  for (uint32_t o = 0; o < scene.objects.size(); ++o) {
    if (scene.objects[o].name == "ceiling") ceiling = o;
  }
  for (const bool cut : {true, false}) {
    SCOPED_TRACE(cut ? "cut" : "not cut");
    a5::RadiositySettings r;
    r.patchSize = 0.06f;
    r.formFactors.hemicubeResolution = 16;
    r.discontinuityMeshing = cut;
    r.quadPatches = false;  // (uncut, the ceiling would be a grid of quads: triangles both ways)
    const auto s = a5::solveScene(scene, r);
    // Ceiling patches with a corner on the lamp's outline (x in [213, 343], z in [227, 332]), outside it.
    double ratio = 0.0;
    int n = 0;
    for (uint32_t i = 0; i < s->mesh().patches.size(); ++i) {
      const a5::Patch& p = s->mesh().patches[i];
      const bool under = p.centre.x > 213 && p.centre.x < 343 && p.centre.z > 227 && p.centre.z < 332;
      if (p.object != ceiling || under) continue;
      for (int k = 0; k < 3; ++k) {
        const Vec3& v = s->mesh().positions[p.vertices[k]];
        const bool onOutline = v.x >= 212.9f && v.x <= 343.1f && v.z >= 226.9f && v.z <= 332.1f;
        if (!onOutline || !(s->shown[i].g > 0.0f)) continue;
        ratio += static_cast<double>(s->vertexShown[p.vertices[k]].g / s->shown[i].g);
        ++n;
      }
    }
    ASSERT_GE(n, 4);
    if (cut)
      EXPECT_GT(ratio / n, 0.8);
    else
      EXPECT_LT(ratio / n, 0.8);  // what it was
  }
}

}  // namespace
}  // namespace ll
