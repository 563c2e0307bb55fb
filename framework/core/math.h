// Vector math for LightLab: GLM types under short names, plus the few helpers
// every module needs. All spaces are right-handed; angles are radians unless
// a name says _deg.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

namespace ll {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Vec4 = glm::vec4;
using Mat3 = glm::mat3;
using Mat4 = glm::mat4;
using Rgb = glm::vec3;  // linear RGB radiance or reflectance, never sRGB-encoded

constexpr float kPi = 3.14159265358979323846f;
constexpr double kPiD = 3.14159265358979323846;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

// v's components as an array, for indexing by a run-time axis in hot loops:
// glm's operator[] is a switch, which compiles to branches that mispredict
// whenever consecutive rays pick other axes.
inline std::array<float, 3> components(const Vec3& v) { return {v.x, v.y, v.z}; }
inline float maxComponent(const Vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }
inline float minComponent(const Vec3& v) { return std::min(v.x, std::min(v.y, v.z)); }
inline float luminance(const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }
inline bool isFinite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline bool isBlack(const Rgb& c) { return c.r <= 0.0f && c.g <= 0.0f && c.b <= 0.0f; }
inline float radians(float deg) { return deg * (kPi / 180.0f); }

// Orthonormal basis around a unit normal n (Duff et al. 2017, "Building an
// Orthonormal Basis, Revisited"): toLocal/toWorld map between world space and
// the frame where n is +z. Precondition: n has unit length.
struct Frame {
  Vec3 s, t, n;
  explicit Frame(const Vec3& normal) : n(normal) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    s = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    t = Vec3(b, sign + n.y * n.y * a, -n.y);
  }
  Vec3 toLocal(const Vec3& v) const { return {glm::dot(v, s), glm::dot(v, t), glm::dot(v, n)}; }
  Vec3 toWorld(const Vec3& v) const { return v.x * s + v.y * t + v.z * n; }
};

// Axis-aligned box; empty when min > max on any axis.
struct Bounds3 {
  Vec3 min{kInfinity};
  Vec3 max{-kInfinity};
  void extend(const Vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void extend(const Bounds3& b) {
    min = glm::min(min, b.min);
    max = glm::max(max, b.max);
  }
  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  Vec3 center() const { return 0.5f * (min + max); }
  Vec3 extent() const { return empty() ? Vec3(0.0f) : max - min; }
  float diagonal() const { return glm::length(extent()); }
  // Half the box's surface area, ex ey + ey ez + ez ex: what the surface area heuristic compares.
  float halfSurfaceArea() const {
    const Vec3 e = extent();
    return e.x * e.y + e.y * e.z + e.z * e.x;
  }
};

}  // namespace ll
