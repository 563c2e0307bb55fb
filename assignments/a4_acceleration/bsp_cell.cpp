#include "bsp_cell.h"

#include <algorithm>
#include <cmath>

namespace ll::a4 {

namespace {

// Keeps the part of `in` with side * (dot(normal, x) - offset) <= 0 in `out`
// (Sutherland-Hodgman against one plane). Points made on the plane are
// appended to `cut`, when given.
void clipPolygon(const std::vector<Vec3>& in, const Vec3& normal, float offset, float side, std::vector<Vec3>& out,
                 std::vector<Vec3>* cut = nullptr) {
  out.clear();
  const size_t n = in.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3& u = in[i];
    const Vec3& v = in[(i + 1) % n];
    const float du = side * (glm::dot(normal, u) - offset), dv = side * (glm::dot(normal, v) - offset);
    if (du <= 0.0f) {
      out.push_back(u);
      if (cut && du == 0.0f) cut->push_back(u);
    }
    if ((du < 0.0f && dv > 0.0f) || (du > 0.0f && dv < 0.0f)) {
      const Vec3 x = u + (du / (du - dv)) * (v - u);
      out.push_back(x);
      if (cut) cut->push_back(x);
    }
  }
  if (out.size() < 3) out.clear();
}

// Twice the vector area of a planar polygon (its normal times twice its area).
Vec3 vectorArea2(const std::vector<Vec3>& p) {
  Vec3 sum(0.0f);
  for (size_t i = 1; i + 1 < p.size(); ++i) sum += glm::cross(p[i] - p[0], p[i + 1] - p[0]);
  return sum;
}

}  // namespace

ConvexCell ConvexCell::box(const Bounds3& b) {
  const auto corner = [&](int k) {
    return Vec3((k & 1) ? b.max.x : b.min.x, (k & 2) ? b.max.y : b.min.y, (k & 4) ? b.max.z : b.min.z);
  };
  // Corner k has bit 0 = x, bit 1 = y, bit 2 = z at max; each face counter-clockwise seen from outside.
  static constexpr int kFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  ConvexCell cell;
  for (const auto& f : kFaces) cell.faces_.push_back({corner(f[0]), corner(f[1]), corner(f[2]), corner(f[3])});
  return cell;
}

float ConvexCell::area() const {
  float sum = 0.0f;
  for (const auto& f : faces_) sum += 0.5f * glm::length(vectorArea2(f));
  return sum;
}

Bounds3 ConvexCell::bounds() const {
  Bounds3 b;
  for (const auto& f : faces_)
    for (const Vec3& p : f) b.extend(p);
  return b;
}

void ConvexCell::splitAreas(const Vec3& normal, float offset, float& below, float& above) const {
  thread_local std::vector<Vec3> part;
  below = above = 0.0f;
  Vec3 cut2(0.0f);  // twice the vector area of the below part's faces: minus the cut's
  for (const auto& f : faces_) {
    clipPolygon(f, normal, offset, 1.0f, part);
    const Vec3 a2 = vectorArea2(part);
    below += 0.5f * glm::length(a2);
    cut2 += a2;
    clipPolygon(f, normal, offset, -1.0f, part);
    above += 0.5f * glm::length(vectorArea2(part));
  }
  const float cut = 0.5f * glm::length(cut2);
  below += cut;
  above += cut;
}

void ConvexCell::split(const Vec3& normal, float offset, ConvexCell& below, ConvexCell& above) const {
  below.faces_.clear();
  above.faces_.clear();
  std::vector<Vec3> part, cut;
  for (const auto& f : faces_) {
    clipPolygon(f, normal, offset, 1.0f, part, &cut);
    if (!part.empty()) below.faces_.push_back(part);
    clipPolygon(f, normal, offset, -1.0f, part);
    if (!part.empty()) above.faces_.push_back(part);
  }
  if (below.faces_.empty() || above.faces_.empty()) return;
  // The cut: the points made on the plane, in angle order around their centre
  // (counter-clockwise about +normal: the below part's outward side).
  Vec3 centre(0.0f);
  for (const Vec3& p : cut) centre += p;
  centre /= static_cast<float>(std::max<size_t>(cut.size(), 1));
  const Vec3 u = glm::normalize(std::abs(normal.x) > 0.9f ? glm::cross(normal, Vec3(0, 1, 0))
                                                           : glm::cross(normal, Vec3(1, 0, 0)));
  const Vec3 v = glm::cross(normal, u);
  std::vector<std::pair<float, Vec3>> byAngle;
  for (const Vec3& p : cut) byAngle.emplace_back(std::atan2(glm::dot(p - centre, v), glm::dot(p - centre, u)), p);
  std::sort(byAngle.begin(), byAngle.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Vec3> cap;
  const float merge = 1e-6f * (glm::length(centre) + bounds().diagonal());
  for (const auto& [angle, p] : byAngle)
    if (cap.empty() || glm::length(p - cap.back()) > merge) cap.push_back(p);
  while (cap.size() > 1 && glm::length(cap.front() - cap.back()) <= merge) cap.pop_back();
  if (cap.size() < 3) return;
  below.faces_.push_back(cap);
  std::reverse(cap.begin(), cap.end());
  above.faces_.push_back(cap);
}

std::vector<std::pair<Vec3, Vec3>> ConvexCell::edges() const {
  std::vector<std::pair<Vec3, Vec3>> out;
  for (const auto& f : faces_)
    for (size_t i = 0; i < f.size(); ++i) out.emplace_back(f[i], f[(i + 1) % f.size()]);
  return out;
}

}  // namespace ll::a4
