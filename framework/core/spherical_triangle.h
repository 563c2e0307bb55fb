// Uniform sampling of the solid angle a triangle subtends (Arvo 1995,
// "Stratified sampling of spherical triangles", SIGGRAPH; in the numerically
// careful form of pbrt-v4, Pharr, Jakob and Humphreys 2023, sec. 6.5.4).
// Used where a point-to-area integral must stay finite right next to the
// area: radiosity's Monte Carlo form factors between patches sharing an edge.
#pragma once

#include <optional>

#include "core/math.h"

namespace ll {

struct SphericalTriangle {
  glm::dvec3 a, b, c;    // unit directions from the viewpoint to the corners
  double solidAngle = 0;  // steradians, in [0, 2 pi)
};

// The triangle (v0, v1, v2) seen from p (world space); nullopt when it is
// degenerate as seen from p (a corner at p, or collinear directions: a solid
// angle of 0).
std::optional<SphericalTriangle> sphericalTriangle(const glm::dvec3& p, const glm::dvec3& v0, const glm::dvec3& v1,
                                                   const glm::dvec3& v2);

// A unit direction inside the spherical triangle, uniform in solid angle
// (pdf 1 / solidAngle) for u uniform in [0, 1)^2.
glm::dvec3 sampleSphericalTriangle(const SphericalTriangle& t, glm::dvec2 u);

}  // namespace ll
