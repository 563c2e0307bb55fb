// Assignment 1 -- A software rasterizer with Blinn-Phong shading. The five
// functions you write. Each lives in its own .cpp file between the markers of
// its task ID; the pipeline (rasterizer.cpp) and the technique `blinn-phong`
// (blinn_phong_technique.cpp) call them. Until you write one, its stub reports
// the task as missing and the task's reference (the course's solution, object
// code) answers in its place, the pixels striped, so the tasks can be done in
// any order. See README.md for the handout and the --reference switches.
#pragma once

#include "core/math.h"
#include "mip_chain.h"
#include "scene/camera.h"

namespace ll::a1 {

// A1.1 Projection. The matrix taking world space to OpenGL clip space for the
// pinhole `camera` (eye, target, up, vertical field of view camera.fovYDeg,
// aspect camera.width / camera.height): view (look-at, right-handed, the eye
// looks down -z) followed by the perspective projection that maps view depth
// -near to NDC z = -1 and -far to +1. Preconditions: 0 < near < far.
Mat4 viewProjection(const Camera& camera, float near, float far);

// A1.2 Edge functions. (b - a) x (p - a), the z component of the 2D cross
// product: twice the signed area of triangle (a, b, p), in screen space
// (x right, y DOWN, units of samples). Compute it in double: for float
// inputs every step is then exact, so a sample lying exactly on an edge
// shared by two triangles gets exactly 0 from both (and the fill rule below
// decides who draws it) instead of a rounding-dependent sign.
double edgeFunction(Vec2 a, Vec2 b, Vec2 p);
// A1.2 Top-left fill rule. For an edge a->b of a triangle whose
// edgeFunction(v0, v1, v2) > 0 (screen y down): true if the edge is a top edge
// (exactly horizontal, the others below it) or a left edge. A sample exactly
// on an edge belongs to the triangle only if the edge is top-left, so a
// sample on an edge shared by two triangles is drawn exactly once.
bool isTopLeft(Vec2 a, Vec2 b);

// A1.3 Z-buffer. The depth test of a fragment at NDC-derived depth z (in
// [0, 1], smaller = nearer) against the z-buffer entry `stored`: if the
// fragment is strictly nearer, store z and return true (draw it); otherwise
// leave `stored` and return false.
bool depthTest(float z, float& stored);

// A1.4 Blinn-Phong. What one light adds at a surface point, split so that a
// texture can scale kd afterwards:  L += kd * diffuse + ks * specular with
//   diffuse  = E * max(0, n.l)
//   specular = E * max(0, n.h)^p  (0 when n.l <= 0: the light is behind the surface)
// where E = I / r^2 is the light's irradiance scale (computed by the caller),
// h = (v + l) / |v + l|. n, v, l are unit vectors; n is on the viewer's side.
struct LightTerms {
  Rgb diffuse{0.0f};
  Rgb specular{0.0f};
};
LightTerms blinnPhong(Vec3 n, Vec3 v, Vec3 l, Rgb irradiance, float shininess);

// A1.5 Texture sampling. The texture colour at uv (repeating; v = 0 is the
// BOTTOM row of mips.level(0), texel (i, j) has its centre at uv
// ((i + 0.5) / w, 1 - (j + 0.5) / h)):
//   Nearest:   the texel of level 0 containing uv;
//   Bilinear:  bilinear between the four nearest texel centres of level 0;
//   Trilinear: lod <= 0: as Bilinear; else linear between Bilinear on levels
//              floor(lod) and floor(lod) + 1, lod clamped to [0, levels - 1].
// lod = log2(texels per sample), computed by the caller.
enum class TextureFilter { Nearest, Bilinear, Trilinear };
Rgb sampleTexture(const MipChain& mips, Vec2 uv, float lod, TextureFilter filter);

}  // namespace ll::a1
