// Watertight ray/triangle intersection (Woop, Benthin and Wald, "Watertight
// Ray/Triangle Intersection", JCGT 2(1), 2013). Rays through a shared edge or
// vertex hit exactly one of the adjacent triangles' closed sets -- never fall
// through a crack. Inline: it sits in every accelerator's inner loop. It
// answers task A2.3, so the student tree holds it as object code only
// (tasks/framework_answer.h).
#pragma once

#include <xmmintrin.h>  // SSE (x86-64 baseline): four triangles at once

#include <cmath>

#include "core/ray.h"
#include "tasks/framework_answer.h"

namespace ll {

// Per-ray constants of the watertight test, computed once per ray.
struct WatertightRay {
  int kx, ky, kz;  // axes permuted so that |dir[kz]| is largest
  float sx, sy, sz;
  Vec3 origin;
  explicit WatertightRay(const Ray& ray);
};

// Tests the triangle (p0, p1, p2) for t in (tmin, tmax). On a hit returns true
// and sets t and the barycentrics b1, b2 of p1 and p2 (b0 = 1 - b1 - b2).
// Both faces hit. Zero-area triangles (repeated or exactly collinear
// vertices: cross(p1 - p0, p2 - p0) == 0) never hit, so no hit ever needs a
// normal that does not exist; the scene loaders drop them as well.
bool intersectTriangle(const WatertightRay& r, const Vec3& p0, const Vec3& p1, const Vec3& p2, float tmin,
                       float tmax, float& t, float& b1, float& b2);

// Four triangles side by side for the four-lane test: v[vertex][axis][lane]
// (world space), 16-byte aligned. A lane without a triangle holds zeros.
struct alignas(16) Triangles4 {
  float v[3][3][4];
};

// WatertightRay's constants broadcast to four lanes, in the test's own frame.
struct WatertightRay4 {
  int kx, ky, kz;
  __m128 origin[3];  // origin[kx], origin[ky], origin[kz]
  __m128 sx, sy, sz;
  __m128 tmin;
  WatertightRay4(const WatertightRay& r, float rayTmin)
      : kx(r.kx), ky(r.ky), kz(r.kz),
        origin{_mm_set1_ps(components(r.origin)[r.kx]), _mm_set1_ps(components(r.origin)[r.ky]),
               _mm_set1_ps(components(r.origin)[r.kz])},
        sx(_mm_set1_ps(r.sx)), sy(_mm_set1_ps(r.sy)), sz(_mm_set1_ps(r.sz)), tmin(_mm_set1_ps(rayTmin)) {}
};

// What the four-lane test found, as bit masks over the lanes.
struct TriangleHits4 {
  unsigned hit = 0;        // hits in (tmin, tmax): t, b1, b2 below, as intersectTriangle() gives them
  unsigned undecided = 0;  // an edge function rounded to 0: intersectTriangle() decides (in double)
  alignas(16) float t[4], b1[4], b2[4];
};

// intersectTriangle() on four triangles at once: its float operations in the same order (x86-64 has no
// FMA to contract them into), so a `hit` lane is a hit it finds, with the very same t, b1 and b2, and a
// lane in neither mask is one it rejects. Every lane whose vertices are all 0 is undecided (the caller's
// empty lanes and other primitives). Precondition: no lane holds a triangle with collinear vertices
// (cross(p1 - p0, p2 - p0) == 0, which intersectTriangle() rejects): store those as all 0.
// tmax: per lane, the bound the caller tests against.
void intersectTriangles4(const WatertightRay4& r, const Triangles4& tris, __m128 tmax, TriangleHits4& out);

#if !LIGHTLAB_STUDENT_TREE  // A2.3's answer: object code only in the student tree
LIGHTLAB_ANSWER_INLINE WatertightRay::WatertightRay(const Ray& ray) : origin(ray.origin) {
  LIGHTLAB_ANSWER_GUARD("A2.3", "ll::WatertightRay (the framework's watertight triangle test)");
  const Vec3 a = glm::abs(ray.dir);
  kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
  const int next = kz == 2 ? 0 : kz + 1, last = next == 2 ? 0 : next + 1;  // (selects, not % 3: per ray)
  const auto d = components(ray.dir);
  const bool flip = d[kz] < 0.0f;  // keep the winding
  kx = flip ? last : next;
  ky = flip ? next : last;
  // sx = d[kx] / d[kz], sy = d[ky] / d[kz], sz = 1 / d[kz]: one SSE division (each lane rounded as divss).
  alignas(16) float q[4];
  _mm_store_ps(q, _mm_div_ps(_mm_setr_ps(d[kx], d[ky], 1.0f, 1.0f), _mm_set1_ps(d[kz])));
  sx = q[0];
  sy = q[1];
  sz = q[2];
}

LIGHTLAB_ANSWER_INLINE bool intersectTriangle(const WatertightRay& r, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                                              float tmin, float tmax, float& t, float& b1, float& b2) {
  LIGHTLAB_ANSWER_GUARD("A2.3", "ll::intersectTriangle (the framework's watertight triangle test)");
  const auto a = components(p0 - r.origin), b = components(p1 - r.origin), c = components(p2 - r.origin);
  const float ax = a[r.kx] - r.sx * a[r.kz], ay = a[r.ky] - r.sy * a[r.kz];
  const float bx = b[r.kx] - r.sx * b[r.kz], by = b[r.ky] - r.sy * b[r.kz];
  const float cx = c[r.kx] - r.sx * c[r.kz], cy = c[r.ky] - r.sy * c[r.kz];
  float u = cx * by - cy * bx;
  float v = ax * cy - ay * cx;
  float w = bx * ay - by * ax;
  if (u == 0.0f || v == 0.0f || w == 0.0f) {  // on an edge: redo in double for a consistent sign
    u = static_cast<float>(static_cast<double>(cx) * static_cast<double>(by) - static_cast<double>(cy) * static_cast<double>(bx));
    v = static_cast<float>(static_cast<double>(ax) * static_cast<double>(cy) - static_cast<double>(ay) * static_cast<double>(cx));
    w = static_cast<float>(static_cast<double>(bx) * static_cast<double>(ay) - static_cast<double>(by) * static_cast<double>(ax));
  }
  if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return false;
  const float det = u + v + w;
  if (det == 0.0f) return false;
  // Collinear vertices shear to a sliver whose rounded edge functions can agree in sign: checked only
  // for rays that passed the edge tests, so the common miss costs nothing.
  if (glm::cross(p1 - p0, p2 - p0) == Vec3(0.0f)) return false;
  const float az = r.sz * a[r.kz], bz = r.sz * b[r.kz], cz = r.sz * c[r.kz];
  const float tScaled = u * az + v * bz + w * cz;
  const float invDet = 1.0f / det;
  const float tHit = tScaled * invDet;
  if (!(tHit > tmin && tHit < tmax)) return false;
  t = tHit;
  b1 = v * invDet;
  b2 = w * invDet;
  return true;
}

LIGHTLAB_ANSWER_INLINE void intersectTriangles4(const WatertightRay4& r, const Triangles4& tris, __m128 tmax,
                                                TriangleHits4& out) {
  LIGHTLAB_ANSWER_GUARD("A2.3", "ll::intersectTriangles4 (the framework's watertight triangle test)");
  __m128 x[3], y[3], z[3];  // the vertices relative to the origin, sheared: ax, ay, az of intersectTriangle()
  for (int k = 0; k < 3; ++k) {
    const __m128 dz = _mm_sub_ps(_mm_load_ps(tris.v[k][r.kz]), r.origin[2]);
    x[k] = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(tris.v[k][r.kx]), r.origin[0]), _mm_mul_ps(r.sx, dz));
    y[k] = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(tris.v[k][r.ky]), r.origin[1]), _mm_mul_ps(r.sy, dz));
    z[k] = _mm_mul_ps(r.sz, dz);
  }
  const __m128 u = _mm_sub_ps(_mm_mul_ps(x[2], y[1]), _mm_mul_ps(y[2], x[1]));
  const __m128 v = _mm_sub_ps(_mm_mul_ps(x[0], y[2]), _mm_mul_ps(y[0], x[2]));
  const __m128 w = _mm_sub_ps(_mm_mul_ps(x[1], y[0]), _mm_mul_ps(y[1], x[0]));
  const __m128 zero = _mm_setzero_ps();
  const __m128 onEdge = _mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(u, zero), _mm_cmpeq_ps(v, zero)), _mm_cmpeq_ps(w, zero));
  const __m128 anyNeg = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(u, zero), _mm_cmplt_ps(v, zero)), _mm_cmplt_ps(w, zero));
  const __m128 anyPos = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(u, zero), _mm_cmpgt_ps(v, zero)), _mm_cmpgt_ps(w, zero));
  const __m128 det = _mm_add_ps(_mm_add_ps(u, v), w);
  const __m128 tScaled = _mm_add_ps(_mm_add_ps(_mm_mul_ps(u, z[0]), _mm_mul_ps(v, z[1])), _mm_mul_ps(w, z[2]));
  const __m128 invDet = _mm_div_ps(_mm_set1_ps(1.0f), det);  // (det 0 off an edge: mixed signs, rejected)
  const __m128 t = _mm_mul_ps(tScaled, invDet);
  const __m128 inRange = _mm_and_ps(_mm_cmpgt_ps(t, r.tmin), _mm_cmplt_ps(t, tmax));
  const __m128 hit = _mm_andnot_ps(_mm_or_ps(_mm_and_ps(anyNeg, anyPos), onEdge), inRange);
  out.hit = static_cast<unsigned>(_mm_movemask_ps(hit));
  out.undecided = static_cast<unsigned>(_mm_movemask_ps(onEdge));
  _mm_store_ps(out.t, t);
  _mm_store_ps(out.b1, _mm_mul_ps(v, invDet));
  _mm_store_ps(out.b2, _mm_mul_ps(w, invDet));
}
#endif

}  // namespace ll
