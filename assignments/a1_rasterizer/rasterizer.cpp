#include "rasterizer.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "a1_tasks.h"

namespace ll::a1 {

double referenceEdgeFunction(Vec2 a, Vec2 b, Vec2 p) {
  const double ax = a.x, ay = a.y;  // float -> double is exact, and so is every step below
  const double bx = static_cast<double>(b.x) - ax, by = static_cast<double>(b.y) - ay;
  const double px = static_cast<double>(p.x) - ax, py = static_cast<double>(p.y) - ay;
  return bx * py - by * px;
}

bool referenceIsTopLeft(Vec2 a, Vec2 b) { return (a.y == b.y && b.x > a.x) || b.y < a.y; }

bool referenceDepthTest(float z, float& stored) {
  if (!(z < stored)) return false;
  stored = z;
  return true;
}

Varyings blend(const Varyings& a, const Varyings& b, const Varyings& c, float b0, float b1, float b2) {
  Varyings v;
  v.position = b0 * a.position + b1 * b.position + b2 * c.position;
  v.normal = b0 * a.normal + b1 * b.normal + b2 * c.normal;
  v.uv = b0 * a.uv + b1 * b.uv + b2 * c.uv;
  v.diffuse = b0 * a.diffuse + b1 * b.diffuse + b2 * c.diffuse;
  v.specular = b0 * a.specular + b1 * b.specular + b2 * c.specular;
  return v;
}

namespace {

constexpr int kTile = 16;  // pixels per tile side

struct ClipVertex {
  Vec4 clip;
  Varyings v;
};

// A triangle after clipping and the viewport transform, ready to scan.
struct ScreenTriangle {
  Vec2 p[3];       // sample-grid coordinates (x right, y down; sample (i, j) centred at (i + 0.5, j + 0.5))
  float z[3];      // depth in [0, 1] (affine in screen space)
  float invW[3];   // 1 / w_clip, for perspective-correct interpolation
  Varyings v[3];
  bool topLeft[3];  // edge k runs from p[(k + 1) % 3] to p[(k + 2) % 3]
  double area;      // edgeFunction(p0, p1, p2) > 0
  Vec3 faceNormal;
  int object;
  int x0, y0, x1, y1;  // sample bounding box, inclusive
};

// Sutherland-Hodgman against the near plane z_clip >= -w_clip: 3 vertices in,
// 0 to 4 out. A crossing is interpolated from the inside vertex, so the two
// triangles sharing a clipped edge get the very same new vertex (no crack).
int clipNear(const ClipVertex (&in)[3], ClipVertex (&out)[4]) {
  int n = 0;
  for (int i = 0; i < 3; ++i) {
    const ClipVertex& a = in[i];
    const ClipVertex& b = in[(i + 1) % 3];
    const float da = a.clip.z + a.clip.w, db = b.clip.z + b.clip.w;
    if (da >= 0.0f) out[n++] = a;
    if ((da >= 0.0f) != (db >= 0.0f)) {
      const ClipVertex& inside = da >= 0.0f ? a : b;
      const ClipVertex& outside = da >= 0.0f ? b : a;
      const float di = inside.clip.z + inside.clip.w, dout = outside.clip.z + outside.clip.w;
      const float t = di / (di - dout);
      out[n].clip = inside.clip + t * (outside.clip - inside.clip);
      out[n].v = blend(inside.v, outside.v, outside.v, 1.0f - t, t, 0.0f);
      ++n;
    }
  }
  return n;
}

// Appends the screen triangles of one draw call, in order.
void setup(const Shader& shader, const DrawCall& draw, const RasterSettings& s, std::vector<ScreenTriangle>& out) {
  const float sw = static_cast<float>(s.width * s.scale), sh = static_cast<float>(s.height * s.scale);
  for (int t = 0; t + 2 < draw.vertexCount; t += 3) {
    ClipVertex in[3];
    for (int k = 0; k < 3; ++k) in[k].clip = shader.vertex(draw.firstVertex + t + k, draw.object, in[k].v);
    const Vec3 face = glm::cross(in[1].v.position - in[0].v.position, in[2].v.position - in[0].v.position);
    const float faceLength = glm::length(face);
    if (!(faceLength > 0.0f)) continue;  // degenerate (or non-finite) triangle: nothing to draw
    ClipVertex poly[4];
    const int n = clipNear(in, poly);
    for (int f = 1; f + 1 < n; ++f) {
      const ClipVertex* c[3] = {&poly[0], &poly[f], &poly[f + 1]};
      ScreenTriangle tri;
      bool finite = true;
      for (int k = 0; k < 3; ++k) {
        const float invW = 1.0f / c[k]->clip.w;  // w >= near > 0 after clipping
        const Vec3 ndc = Vec3(c[k]->clip) * invW;
        tri.p[k] = Vec2((ndc.x * 0.5f + 0.5f) * sw, (0.5f - ndc.y * 0.5f) * sh);
        tri.z[k] = ndc.z * 0.5f + 0.5f;
        tri.invW[k] = invW;
        tri.v[k] = c[k]->v;
        finite = finite && std::isfinite(tri.p[k].x) && std::isfinite(tri.p[k].y) && std::isfinite(invW);
      }
      if (!finite) continue;
      tri.area = edgeFunction(tri.p[0], tri.p[1], tri.p[2]);
      if (tri.area == 0.0 || !std::isfinite(tri.area)) continue;
      if (tri.area < 0.0) {  // no back-face culling: both windings are drawn
        std::swap(tri.p[1], tri.p[2]);
        std::swap(tri.z[1], tri.z[2]);
        std::swap(tri.invW[1], tri.invW[2]);
        std::swap(tri.v[1], tri.v[2]);
        tri.area = -tri.area;
      }
      for (int k = 0; k < 3; ++k) tri.topLeft[k] = isTopLeft(tri.p[(k + 1) % 3], tri.p[(k + 2) % 3]);
      const float minX = std::min({tri.p[0].x, tri.p[1].x, tri.p[2].x});
      const float maxX = std::max({tri.p[0].x, tri.p[1].x, tri.p[2].x});
      const float minY = std::min({tri.p[0].y, tri.p[1].y, tri.p[2].y});
      const float maxY = std::max({tri.p[0].y, tri.p[1].y, tri.p[2].y});
      // Samples i with minX <= i + 0.5 <= maxX, clamped to the target.
      tri.x0 = static_cast<int>(std::max(0.0f, std::ceil(minX - 0.5f)));
      tri.y0 = static_cast<int>(std::max(0.0f, std::ceil(minY - 0.5f)));
      tri.x1 = static_cast<int>(std::min(sw - 1.0f, std::floor(maxX - 0.5f)));
      tri.y1 = static_cast<int>(std::min(sh - 1.0f, std::floor(maxY - 0.5f)));
      if (tri.x0 > tri.x1 || tri.y0 > tri.y1) continue;
      tri.faceNormal = face / faceLength;
      tri.object = draw.object;
      out.push_back(tri);
    }
  }
}

// Perspective-correct barycentrics from screen-space ones.
Vec3 perspective(const ScreenTriangle& t, Vec3 b) {
  const Vec3 q(b.x * t.invW[0], b.y * t.invW[1], b.z * t.invW[2]);
  return q / (q.x + q.y + q.z);
}

Vec2 uvAt(const ScreenTriangle& t, Vec3 b) {
  const Vec3 pb = perspective(t, b);
  return pb.x * t.v[0].uv + pb.y * t.v[1].uv + pb.z * t.v[2].uv;
}

// Draws triangle `t` into the tile whose samples are [sx0, sx1) x [sy0, sy1).
void scanTriangle(const Shader& shader, const ScreenTriangle& t, int sx0, int sy0, int sx1, int sy1,
                  std::vector<Rgb>& color, std::vector<float>& depth, std::vector<uint8_t>& stub,
                  uint64_t& nonFinite) {
  const int tw = sx1 - sx0;
  const int x0 = std::max(t.x0, sx0), x1 = std::min(t.x1, sx1 - 1);
  const int y0 = std::max(t.y0, sy0), y1 = std::min(t.y1, sy1 - 1);
  // Screen-space barycentrics are affine: one sample step adds a constant.
  const Vec3 ddx = Vec3(t.p[1].y - t.p[2].y, t.p[2].y - t.p[0].y, t.p[0].y - t.p[1].y) / static_cast<float>(t.area);
  const Vec3 ddy = Vec3(t.p[2].x - t.p[1].x, t.p[0].x - t.p[2].x, t.p[1].x - t.p[0].x) / static_cast<float>(t.area);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const Vec2 p(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      const size_t i = static_cast<size_t>(y - sy0) * static_cast<size_t>(tw) + static_cast<size_t>(x - sx0);
      double e[3];
      bool inside = true;
      for (int k = 0; k < 3 && inside; ++k) {
        e[k] = edgeFunction(t.p[(k + 1) % 3], t.p[(k + 2) % 3], p);
        inside = e[k] > 0.0 || (e[k] == 0.0 && t.topLeft[k]);
      }
      if (inside) {
        const Vec3 b(static_cast<float>(e[0] / t.area), static_cast<float>(e[1] / t.area),
                     static_cast<float>(e[2] / t.area));
        const float z = b.x * t.z[0] + b.y * t.z[1] + b.z * t.z[2];
        if (z >= 0.0f && depthTest(z, depth[i])) {
          Fragment f;
          const Vec3 pb = perspective(t, b);
          f.in = blend(t.v[0], t.v[1], t.v[2], pb.x, pb.y, pb.z);
          f.faceNormal = t.faceNormal;
          f.object = t.object;
          f.sample = glm::ivec2(x, y);
          f.uvDx = uvAt(t, b + ddx) - f.in.uv;
          f.uvDy = uvAt(t, b + ddy) - f.in.uv;
          color[i] = shader.fragment(f);
          if (!isFinite(color[i])) {  // never a NaN in a pixel: counted and zeroed
            color[i] = Rgb(0.0f);
            ++nonFinite;
          }
        }
      }
      if (takeStubFlag()) stub[i] = 1;
    }
}

}  // namespace

uint64_t rasterize(const Shader& shader, const std::vector<DrawCall>& draws, const RasterSettings& s,
                   FrameBuffer& fb, const std::atomic<bool>& cancel) {
  const ScopedTaskLog scopedLog(s.taskLog);
  takeStubFlag();
  std::vector<ScreenTriangle> tris;
  for (const DrawCall& d : draws) setup(shader, d, s, tris);
  const bool setupStub = takeStubFlag();  // a stub in the vertex stage or setup touches every pixel
  if (cancel) return 0;

  // Binning: each tile's triangles, in submission order.
  const int scale = s.scale, tileSamples = kTile * scale;
  const int tilesX = (s.width + kTile - 1) / kTile, tilesY = (s.height + kTile - 1) / kTile;
  std::vector<std::vector<uint32_t>> bins(static_cast<size_t>(tilesX) * static_cast<size_t>(tilesY));
  for (size_t k = 0; k < tris.size(); ++k) {
    const ScreenTriangle& t = tris[k];
    for (int ty = t.y0 / tileSamples; ty <= t.y1 / tileSamples; ++ty)
      for (int tx = t.x0 / tileSamples; tx <= t.x1 / tileSamples; ++tx)
        bins[static_cast<size_t>(ty) * static_cast<size_t>(tilesX) + static_cast<size_t>(tx)].push_back(
            static_cast<uint32_t>(k));
  }

  const float norm = 1.0f / static_cast<float>(scale * scale);
  std::atomic<uint64_t> nonFinite{0};
  tbb::parallel_for(tbb::blocked_range<int>(0, tilesX * tilesY), [&](const tbb::blocked_range<int>& range) {
    const ScopedTaskLog log(s.taskLog);
    std::vector<Rgb> color;
    std::vector<float> depth;
    std::vector<uint8_t> stub;
    uint64_t localNonFinite = 0;
    for (int tile = range.begin(); tile < range.end(); ++tile) {
      if (cancel.load(std::memory_order_relaxed)) break;
      const int px0 = (tile % tilesX) * kTile, py0 = (tile / tilesX) * kTile;
      const int px1 = std::min(px0 + kTile, s.width), py1 = std::min(py0 + kTile, s.height);
      // The tile's samples: [sx0, sx1) x [sy0, sy1) of the sample grid.
      const int sx0 = px0 * scale, sx1 = px1 * scale, sy0 = py0 * scale, sy1 = py1 * scale;
      const int tw = sx1 - sx0;
      const size_t count = static_cast<size_t>(tw) * static_cast<size_t>(sy1 - sy0);
      color.assign(count, s.background);
      depth.assign(count, 1.0f);  // the far plane
      stub.assign(count, setupStub ? 1 : 0);
      takeStubFlag();
      for (const uint32_t k : bins[static_cast<size_t>(tile)])
        scanTriangle(shader, tris[k], sx0, sy0, sx1, sy1, color, depth, stub, localNonFinite);
      // Box filter of each pixel's scale x scale samples.
      for (int y = py0; y < py1; ++y)
        for (int x = px0; x < px1; ++x) {
          Rgb sum(0.0f);
          bool marked = false;
          for (int sy = 0; sy < scale; ++sy)
            for (int sx = 0; sx < scale; ++sx) {
              const size_t i = static_cast<size_t>((y - py0) * scale + sy) * static_cast<size_t>(tw) +
                               static_cast<size_t>((x - px0) * scale + sx);
              sum += color[i];
              marked = marked || stub[i] != 0;
            }
          fb.add(x, y, sum * norm);
          if (marked) fb.markStub(x, y);
        }
    }
    nonFinite += localNonFinite;
  });
  return nonFinite.load();
}

}  // namespace ll::a1
