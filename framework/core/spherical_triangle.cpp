#include "core/spherical_triangle.h"

#include <algorithm>
#include <cmath>

namespace ll {

namespace {

// The angle between unit vectors, accurate near 0 and pi.
double angleBetween(const glm::dvec3& x, const glm::dvec3& y) {
  if (glm::dot(x, y) < 0.0) return kPiD - 2.0 * std::asin(std::min(glm::length(x + y) / 2.0, 1.0));
  return 2.0 * std::asin(std::min(glm::length(y - x) / 2.0, 1.0));
}

// v with its component along unit w removed.
glm::dvec3 gramSchmidt(const glm::dvec3& v, const glm::dvec3& w) { return v - glm::dot(v, w) * w; }

glm::dvec3 unitOrZero(const glm::dvec3& v) {
  const double l = glm::length(v);
  return l > 0.0 ? v / l : glm::dvec3(0.0);
}

}  // namespace

std::optional<SphericalTriangle> sphericalTriangle(const glm::dvec3& p, const glm::dvec3& v0, const glm::dvec3& v1,
                                                   const glm::dvec3& v2) {
  const glm::dvec3 d0 = v0 - p, d1 = v1 - p, d2 = v2 - p;
  const double l0 = glm::length(d0), l1 = glm::length(d1), l2 = glm::length(d2);
  if (!(l0 > 0.0 && l1 > 0.0 && l2 > 0.0)) return std::nullopt;
  SphericalTriangle t{d0 / l0, d1 / l1, d2 / l2, 0.0};
  // Van Oosterom and Strackee (1983): tan(Omega / 2) = a.(b x c) / (1 + a.b + b.c + c.a).
  const double triple = std::abs(glm::dot(t.a, glm::cross(t.b, t.c)));
  const double denominator = 1.0 + glm::dot(t.a, t.b) + glm::dot(t.b, t.c) + glm::dot(t.c, t.a);
  t.solidAngle = 2.0 * std::atan2(triple, denominator);
  if (!(t.solidAngle > 0.0)) return std::nullopt;
  return t;
}

glm::dvec3 sampleSphericalTriangle(const SphericalTriangle& t, glm::dvec2 u) {
  const glm::dvec3 &a = t.a, &b = t.b, &c = t.c;
  // The great circles' normals and the triangle's angles at a, b, c.
  const glm::dvec3 nab = unitOrZero(glm::cross(a, b)), nbc = unitOrZero(glm::cross(b, c)),
                   nca = unitOrZero(glm::cross(c, a));
  const double alpha = angleBetween(nab, -nca), beta = angleBetween(nbc, -nab), gamma = angleBetween(nca, -nbc);
  // The sub-triangle (a, b, c') with area u.x times the whole: find c' on the arc from a to c.
  const double areaPlusPi = std::lerp(kPiD, alpha + beta + gamma, u.x);
  const double cosAlpha = std::cos(alpha), sinAlpha = std::sin(alpha);
  const double sinPhi = std::sin(areaPlusPi) * cosAlpha - std::cos(areaPlusPi) * sinAlpha;
  const double cosPhi = std::cos(areaPlusPi) * cosAlpha + std::sin(areaPlusPi) * sinAlpha;
  const double k1 = cosPhi + cosAlpha, k2 = sinPhi - sinAlpha * glm::dot(a, b);
  const double denominator = (k2 * sinPhi + k1 * cosPhi) * sinAlpha;
  double cosB = denominator != 0.0 ? (k2 + (k2 * cosPhi - k1 * sinPhi) * cosAlpha) / denominator : 1.0;
  cosB = std::clamp(std::isfinite(cosB) ? cosB : 1.0, -1.0, 1.0);
  const double sinB = std::sqrt(std::max(0.0, 1.0 - cosB * cosB));
  const glm::dvec3 cPrime = cosB * a + sinB * unitOrZero(gramSchmidt(c, a));
  // Then uniformly in solid angle along the arc from b to c'.
  const double cosTheta = 1.0 - u.y * (1.0 - glm::dot(cPrime, b));
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return unitOrZero(cosTheta * b + sinTheta * unitOrZero(gramSchmidt(cPrime, b)));
}

}  // namespace ll
