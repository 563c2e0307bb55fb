#include "discontinuity_cuts.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace ll::a5 {

namespace {

// The object's triangles (none if it has a sphere).
std::vector<Triangle3> objectTriangles(const Scene& scene, uint32_t o) {
  const Geometry& g = scene.geometry;
  const SceneObject& object = scene.objects[o];
  std::vector<Triangle3> out;
  for (uint32_t prim = object.firstPrim; prim < object.firstPrim + object.primCount; ++prim) {
    if (!g.isTriangle(prim)) return {};
    const glm::uvec3& t = g.triangles[prim];
    out.push_back({g.positions[t.x], g.positions[t.y], g.positions[t.z]});
  }
  return out;
}

// The common unit normal and a point of a planar set of triangles, if they are one plane (within tolerance).
bool planeOf(const std::vector<Triangle3>& triangles, float tolerance, Vec3& normal, Vec3& point) {
  if (triangles.empty()) return false;
  Vec3 sum(0.0f);
  for (const Triangle3& t : triangles) sum += glm::cross(t[1] - t[0], t[2] - t[0]);
  if (!(glm::length(sum) > 0.0f)) return false;
  normal = glm::normalize(sum);
  point = triangles[0][0];
  for (const Triangle3& t : triangles)
    for (const Vec3& v : t)
      if (std::abs(glm::dot(normal, v - point)) > tolerance) return false;
  return true;
}

using Key = std::tuple<float, float, float>;
Key key(const Vec3& v) { return {v.x, v.y, v.z}; }

// Edges used by one triangle only: the object's outline.
std::vector<std::pair<Vec3, Vec3>> boundaryEdges(const std::vector<Triangle3>& triangles) {
  std::map<std::pair<Key, Key>, int> uses;
  const auto edgeKey = [](const Vec3& a, const Vec3& b) {
    return key(a) < key(b) ? std::make_pair(key(a), key(b)) : std::make_pair(key(b), key(a));
  };
  for (const Triangle3& t : triangles)
    for (int k = 0; k < 3; ++k) ++uses[edgeKey(t[k], t[(k + 1) % 3])];
  std::vector<std::pair<Vec3, Vec3>> out;
  for (const Triangle3& t : triangles)
    for (int k = 0; k < 3; ++k)
      if (uses[edgeKey(t[k], t[(k + 1) % 3])] == 1) out.emplace_back(t[k], t[(k + 1) % 3]);
  return out;
}

// Whether p (in the plane of t) lies inside triangle t, `margin` (scene units) inside its edges.
bool insideTriangle(const Triangle3& t, const Vec3& normal, const Vec3& p, float margin) {
  for (int k = 0; k < 3; ++k) {
    const Vec3 edge = t[(k + 1) % 3] - t[k];
    const Vec3 inward = glm::normalize(glm::cross(normal, edge));
    if (glm::dot(inward, p - t[k]) < margin) return false;
  }
  return true;
}

// The point where the line crosses edge (a, b), computed from the edge's
// lexicographically smaller end, so both triangles on a shared edge get the
// same float point.
Vec3 crossing(const Vec3& a, float da, const Vec3& b, float db) {
  if (key(b) < key(a)) return crossing(b, db, a, da);
  return a + (da / (da - db)) * (b - a);
}

}  // namespace

std::vector<CutLine> contactLines(const Scene& scene, uint32_t o, float tolerance) {
  const std::vector<Triangle3> receiver = objectTriangles(scene, o);
  Vec3 normal, point;
  if (!planeOf(receiver, tolerance, normal, point)) return {};
  struct Candidate {
    float distance;  // of the segment's midpoint from the receiver's centre
    CutLine line;
  };
  Vec3 centre(0.0f);
  for (const Triangle3& t : receiver) centre += (t[0] + t[1] + t[2]) / (3.0f * static_cast<float>(receiver.size()));
  const std::vector<std::pair<Vec3, Vec3>> receiverOutline = boundaryEdges(receiver);
  std::vector<Candidate> candidates;
  for (uint32_t q = 0; q < scene.objects.size(); ++q) {
    if (q == o) continue;
    const std::vector<Triangle3> source = objectTriangles(scene, q);
    Vec3 sourceNormal, sourcePoint;
    if (!planeOf(source, tolerance, sourceNormal, sourcePoint)) continue;
    for (const auto& [a, b] : boundaryEdges(source)) {
      if (std::abs(glm::dot(normal, a - point)) > tolerance || std::abs(glm::dot(normal, b - point)) > tolerance)
        continue;  // not lying in the receiver's plane
      // Projected into the plane; its midpoint must be over the receiver, not on its outline (a wall
      // standing on the floor's edge marks no jump inside the floor).
      const Vec3 pa = a - glm::dot(normal, a - point) * normal, pb = b - glm::dot(normal, b - point) * normal;
      const Vec3 mid = 0.5f * (pa + pb);
      if (!(glm::length(pb - pa) > tolerance)) continue;
      const bool over = std::any_of(receiver.begin(), receiver.end(),
                                    [&](const Triangle3& t) { return insideTriangle(t, normal, mid, -tolerance); });
      const bool onOutline = std::any_of(receiverOutline.begin(), receiverOutline.end(), [&](const auto& edge) {
        const Vec3 d = edge.second - edge.first;
        const float along = glm::dot(mid - edge.first, d) / glm::dot(d, d);
        return along >= 0.0f && along <= 1.0f && glm::length(edge.first + along * d - mid) <= tolerance;
      });
      if (!over || onOutline) continue;
      candidates.push_back({glm::length(mid - centre), {pa, glm::normalize(pb - pa), glm::length(pb - pa)}});
    }
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& x, const Candidate& y) { return x.distance < y.distance; });
  std::vector<CutLine> lines;
  for (const Candidate& c : candidates) {
    if (lines.size() >= kMaxCutLines) break;
    // The same line twice (two edges of one straight outline) cuts once.
    const bool known = std::any_of(lines.begin(), lines.end(), [&](const CutLine& l) {
      const Vec3 off = c.line.point - l.point;
      return std::abs(glm::dot(l.direction, c.line.direction)) > 1.0f - 1e-6f &&
             glm::length(off - glm::dot(off, l.direction) * l.direction) <= tolerance;
    });
    if (!known) lines.push_back(c.line);
  }
  return lines;
}

std::vector<Triangle3> cutTriangles(std::vector<Triangle3> triangles, const std::vector<CutLine>& lines, float snap) {
  if (triangles.empty() || lines.empty()) return triangles;
  Vec3 normal = glm::cross(triangles[0][1] - triangles[0][0], triangles[0][2] - triangles[0][0]);
  normal = glm::normalize(normal);
  // Convex polygons, cut line by line, triangulated as fans at the end.
  std::vector<std::vector<Vec3>> polygons;
  for (const Triangle3& t : triangles) polygons.push_back({t[0], t[1], t[2]});
  for (const CutLine& line : lines) {
    const Vec3 across = glm::normalize(glm::cross(normal, line.direction));  // signed distance direction
    std::vector<std::vector<Vec3>> next;
    for (const std::vector<Vec3>& poly : polygons) {
      std::vector<float> d(poly.size());
      bool below = false, above = false;
      for (size_t k = 0; k < poly.size(); ++k) {
        d[k] = glm::dot(across, poly[k] - line.point);
        if (std::abs(d[k]) <= snap) d[k] = 0.0f;  // on the line
        below = below || d[k] < 0.0f;
        above = above || d[k] > 0.0f;
      }
      if (!(below && above)) {
        next.push_back(poly);
        continue;
      }
      std::vector<Vec3> negative, positive;
      for (size_t k = 0; k < poly.size(); ++k) {
        const size_t n = (k + 1) % poly.size();
        if (d[k] <= 0.0f) negative.push_back(poly[k]);
        if (d[k] >= 0.0f) positive.push_back(poly[k]);
        if ((d[k] < 0.0f && d[n] > 0.0f) || (d[k] > 0.0f && d[n] < 0.0f)) {
          const Vec3 x = crossing(poly[k], d[k], poly[n], d[n]);
          negative.push_back(x);
          positive.push_back(x);
        }
      }
      next.push_back(negative);
      next.push_back(positive);
    }
    polygons.swap(next);
  }
  // A cut polygon may have corners in a straight line (where a neighbour's cut
  // crossed a shared edge); a fan from a corner would drop them (T-vertices),
  // a fan from the centroid keeps every one.
  std::vector<Triangle3> out;
  for (const std::vector<Vec3>& poly : polygons) {
    if (poly.size() == 3) {
      out.push_back({poly[0], poly[1], poly[2]});
      continue;
    }
    Vec3 centroid(0.0f);
    for (const Vec3& v : poly) centroid += v / static_cast<float>(poly.size());
    for (size_t k = 0; k < poly.size(); ++k) {
      const Triangle3 t{centroid, poly[k], poly[(k + 1) % poly.size()]};
      if (glm::length(glm::cross(t[1] - t[0], t[2] - t[0])) > 0.0f) out.push_back(t);
    }
  }
  return out;
}

}  // namespace ll::a5
