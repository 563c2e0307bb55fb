// The tree of rays one pixel sample spawns (camera ray, reflected and
// refracted rays, shadow rays), recorded for the ray-tree inspector:
// `lightlab trace SCENE --pixel X Y -t whitted --json` prints it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/math.h"
#include "core/ray.h"

namespace ll {

struct RayTreeNode {
  RayKind kind = RayKind::Camera;
  int parent = -1;  // index into RayTree::nodes; -1 for the camera ray
  int depth = 0;    // 0 = camera ray; shadow rays share their surface's depth
  Vec3 origin{0.0f}, direction{0.0f};
  Rgb throughput{1.0f};  // weight of this ray's radiance in the pixel (attenuation by the media included)
  bool intersected = false;  // false: the recursion stopped before tracing it (depth or weight)
  // Where the ray ended: a surface, or nothing (background, or the light for a shadow ray).
  bool hit = false;
  float t = 0.0f;
  Vec3 position{0.0f}, normal{0.0f};  // normal: shading normal on the incoming side
  std::string object, material;
  bool entering = false;                 // the ray arrived on the front side
  float n1 = 1.0f, n2 = 1.0f;            // refractive indices before and behind the surface (dielectrics)
  std::optional<float> fresnel;          // reflectance F at a dielectric (transmitted share 1 - F)
  bool totalInternalReflection = false;
  Rgb absorption{1.0f};                  // Beer-Lambert exp(-sigma t) over the segment
  Rgb shadowTransmittance{1.0f};         // shadow rays: how much light gets through (0 = blocked)
  Rgb local{0.0f};        // emitted + local (ambient, Blinn-Phong) radiance at the hit, before weighting
  Rgb radiance{0.0f};     // radiance arriving along this ray (what the recursion returned)
  Rgb contribution{0.0f}; // throughput * absorption * local: this node's share of the pixel
};

struct RayTree {
  std::vector<RayTreeNode> nodes;  // parents before children
  Rgb pixel{0.0f};                 // the sample's radiance = sum of the contributions
};

}  // namespace ll
