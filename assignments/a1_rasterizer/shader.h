// The programmable stages of the pipeline, in the style of tinyrenderer: a
// vertex function (one mesh vertex -> clip position + varyings) and a
// fragment function (interpolated varyings -> colour of one sample).
#pragma once

#include "core/math.h"

namespace ll::a1 {

// What the vertex stage hands to the fragment stage, interpolated
// perspective-correctly over the triangle. World space.
struct Varyings {
  Vec3 position{0.0f};
  Vec3 normal{0.0f};    // not normalized after interpolation
  Vec2 uv{0.0f};
  Rgb diffuse{0.0f};    // Gouraud: the lights' diffuse sum D at the vertex
  Rgb specular{0.0f};   // Gouraud: the lights' specular sum S at the vertex
};

// b0 a + b1 b + b2 c.
Varyings blend(const Varyings& a, const Varyings& b, const Varyings& c, float b0, float b1, float b2);

// One covered, depth-test-passing sample.
struct Fragment {
  Varyings in;
  Vec3 faceNormal{0.0f};  // the (unclipped) triangle's unit world-space normal, either side
  Vec2 uvDx{0.0f}, uvDy{0.0f};  // d uv / d sample along screen x and y (for the mip level)
  int object = 0;               // the scene object (draw call) the triangle belongs to
  glm::ivec2 sample{0};         // the sample's column and row on the supersampled grid
};

class Shader {
 public:
  virtual ~Shader() = default;
  // Vertex `index` of the mesh, drawn as part of scene object `object`:
  // returns its clip-space position (OpenGL convention), fills `out`.
  virtual Vec4 vertex(int index, int object, Varyings& out) const = 0;
  // Colour (linear radiance) of one sample.
  virtual Rgb fragment(const Fragment& f) const = 0;
};

}  // namespace ll::a1
