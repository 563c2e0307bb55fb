#include "rasterizer.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "a1_tasks.h"

namespace ll::a1 {

Varyings blend(const Varyings& a, const Varyings& b, const Varyings& c, float b0, float b1, float b2) {
  Varyings v;
  v.position = b0 * a.position + b1 * b.position + b2 * c.position;
  v.normal = b0 * a.normal + b1 * b.normal + b2 * c.normal;
  v.uv = b0 * a.uv + b1 * b.uv + b2 * c.uv;
  v.diffuse = b0 * a.diffuse + b1 * b.diffuse + b2 * c.diffuse;
  v.specular = b0 * a.specular + b1 * b.specular + b2 * c.specular;
  return v;
}

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

RasterWorkspace::RasterWorkspace() = default;
RasterWorkspace::~RasterWorkspace() = default;

namespace {

constexpr int kTile = 16;              // pixels per tile side
constexpr int kChunkTriangles = 2048;  // input triangles per setup task
constexpr uint32_t kChunkShift = 12;   // a chunk yields <= 2 * kChunkTriangles <= 2^12 screen triangles

struct ClipVertex {
  Vec4 clip;
  Varyings v;
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

// Appends the screen triangles of triangles [first, last) of one draw call, in order.
void setup(const Shader& shader, const DrawCall& draw, int first, int last, const RasterSettings& s,
           std::vector<ScreenTriangle>& out) {
  const float sw = static_cast<float>(s.width * s.scale), sh = static_cast<float>(s.height * s.scale);
  for (int t = 3 * first; t < 3 * last; t += 3) {
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

// One tile's samples [sx0, sx1) x [sy0, sy1) of the supersampled grid.
struct Tile {
  int sx0, sy0, sx1, sy1;
  int width() const { return sx1 - sx0; }
  size_t index(int x, int y) const {
    return static_cast<size_t>(y - sy0) * static_cast<size_t>(width()) + static_cast<size_t>(x - sx0);
  }
};

// Per-sample state of a tile: the z-buffer and, per sample, the fragment that
// survived it so far (its triangle and screen-space barycentrics).
struct TileBuffers {
  static constexpr uint32_t kNone = ~0u;
  std::vector<float> depth;
  std::vector<uint32_t> triangle;  // reference into the workspace, or kNone
  std::vector<Vec3> barycentric;
  std::vector<Rgb> color;
  std::vector<uint8_t> stub;
};

// Visibility pass of triangle `t` (reference `ref`) over the tile: coverage
// with the fill rule (A1.2), then the depth test (A1.3).
void coverTriangle(const ScreenTriangle& t, uint32_t ref, const Tile& tile, TileBuffers& buf) {
  const int x0 = std::max(t.x0, tile.sx0), x1 = std::min(t.x1, tile.sx1 - 1);
  const int y0 = std::max(t.y0, tile.sy0), y1 = std::min(t.y1, tile.sy1 - 1);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const Vec2 p(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      const size_t i = tile.index(x, y);
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
        if (z >= 0.0f && depthTest(z, buf.depth[i])) {
          buf.triangle[i] = ref;
          buf.barycentric[i] = b;
        }
      }
      if (takeStubFlag()) buf.stub[i] = 1;
    }
}

// Fragment stage of one sample whose surviving fragment lies on `t` at
// screen-space barycentrics b.
Rgb shadeSample(const Shader& shader, const ScreenTriangle& t, Vec3 b, int x, int y, uint64_t& nonFinite) {
  // Screen-space barycentrics are affine: one sample step adds a constant.
  const Vec3 ddx = Vec3(t.p[1].y - t.p[2].y, t.p[2].y - t.p[0].y, t.p[0].y - t.p[1].y) / static_cast<float>(t.area);
  const Vec3 ddy = Vec3(t.p[2].x - t.p[1].x, t.p[0].x - t.p[2].x, t.p[1].x - t.p[0].x) / static_cast<float>(t.area);
  Fragment f;
  const Vec3 pb = perspective(t, b);
  f.in = blend(t.v[0], t.v[1], t.v[2], pb.x, pb.y, pb.z);
  f.faceNormal = t.faceNormal;
  f.object = t.object;
  f.sample = glm::ivec2(x, y);
  f.uvDx = uvAt(t, b + ddx) - f.in.uv;
  f.uvDy = uvAt(t, b + ddy) - f.in.uv;
  const Rgb c = shader.fragment(f);
  if (isFinite(c)) return c;
  ++nonFinite;  // never a NaN in a pixel: counted and drawn as 0
  return Rgb(0.0f);
}

}  // namespace

uint64_t rasterize(const Shader& shader, const std::vector<DrawCall>& draws, const RasterSettings& s,
                   FrameBuffer& fb, const std::atomic<bool>& cancel) {
  RasterWorkspace workspace;
  return rasterize(workspace, shader, draws, s, fb, cancel);
}

uint64_t rasterize(RasterWorkspace& ws, const Shader& shader, const std::vector<DrawCall>& draws,
                   const RasterSettings& s, FrameBuffer& fb, const std::atomic<bool>& cancel) {
  // Vertex stage and setup, in chunks of at most kChunkTriangles triangles of one draw call.
  struct Chunk {
    size_t draw;
    int first, last;
  };
  std::vector<Chunk> chunks;
  for (size_t d = 0; d < draws.size(); ++d)
    for (int first = 0; first < draws[d].vertexCount / 3; first += kChunkTriangles)
      chunks.push_back({d, first, std::min(first + kChunkTriangles, draws[d].vertexCount / 3)});
  if (ws.chunks.size() < chunks.size()) ws.chunks.resize(chunks.size());
  std::atomic<bool> setupStub{false};  // a stub in the vertex stage or setup touches every pixel
  tbb::parallel_for(size_t{0}, chunks.size(), [&](size_t c) {
    const ScopedTaskLog log(s.taskLog);
    takeStubFlag();
    ws.chunks[c].clear();
    setup(shader, draws[chunks[c].draw], chunks[c].first, chunks[c].last, s, ws.chunks[c]);
    if (takeStubFlag()) setupStub = true;
  });
  if (cancel) return 0;

  // Binning: each tile's triangles, in submission order. A reference is
  // (chunk << kChunkShift) | index within the chunk.
  const int scale = s.scale, tileSamples = kTile * scale;
  const int tilesX = (s.width + kTile - 1) / kTile, tilesY = (s.height + kTile - 1) / kTile;
  ws.bins.resize(static_cast<size_t>(tilesX) * static_cast<size_t>(tilesY));
  for (auto& bin : ws.bins) bin.clear();
  for (size_t c = 0; c < chunks.size(); ++c)
    for (size_t k = 0; k < ws.chunks[c].size(); ++k) {
      const ScreenTriangle& t = ws.chunks[c][k];
      const auto ref = static_cast<uint32_t>((c << kChunkShift) | k);
      for (int ty = t.y0 / tileSamples; ty <= t.y1 / tileSamples; ++ty)
        for (int tx = t.x0 / tileSamples; tx <= t.x1 / tileSamples; ++tx)
          ws.bins[static_cast<size_t>(ty) * static_cast<size_t>(tilesX) + static_cast<size_t>(tx)].push_back(ref);
    }
  const auto triangle = [&](uint32_t ref) -> const ScreenTriangle& {
    return ws.chunks[ref >> kChunkShift][ref & ((1u << kChunkShift) - 1)];
  };

  const float norm = 1.0f / static_cast<float>(scale * scale);
  std::atomic<uint64_t> nonFinite{0};
  tbb::parallel_for(tbb::blocked_range<int>(0, tilesX * tilesY), [&](const tbb::blocked_range<int>& range) {
    const ScopedTaskLog log(s.taskLog);
    TileBuffers buf;
    uint64_t localNonFinite = 0;
    for (int tileIndex = range.begin(); tileIndex < range.end(); ++tileIndex) {
      if (cancel.load(std::memory_order_relaxed)) break;
      const int px0 = (tileIndex % tilesX) * kTile, py0 = (tileIndex / tilesX) * kTile;
      const int px1 = std::min(px0 + kTile, s.width), py1 = std::min(py0 + kTile, s.height);
      const Tile tile{px0 * scale, py0 * scale, px1 * scale, py1 * scale};
      const size_t count = static_cast<size_t>(tile.width()) * static_cast<size_t>(tile.sy1 - tile.sy0);
      buf.depth.assign(count, 1.0f);  // the far plane
      buf.triangle.assign(count, TileBuffers::kNone);
      buf.barycentric.resize(count);
      buf.color.assign(count, s.background);
      buf.stub.assign(count, setupStub ? 1 : 0);
      takeStubFlag();
      for (const uint32_t ref : ws.bins[static_cast<size_t>(tileIndex)]) coverTriangle(triangle(ref), ref, tile, buf);
      // Shading pass: the fragment that won each sample, once.
      for (int y = tile.sy0; y < tile.sy1; ++y)
        for (int x = tile.sx0; x < tile.sx1; ++x) {
          const size_t i = tile.index(x, y);
          if (buf.triangle[i] == TileBuffers::kNone) continue;
          buf.color[i] = shadeSample(shader, triangle(buf.triangle[i]), buf.barycentric[i], x, y, localNonFinite);
          if (takeStubFlag()) buf.stub[i] = 1;
        }
      // Box filter of each pixel's scale x scale samples.
      for (int y = py0; y < py1; ++y)
        for (int x = px0; x < px1; ++x) {
          Rgb sum(0.0f);
          bool marked = false;
          for (int sy = 0; sy < scale; ++sy)
            for (int sx = 0; sx < scale; ++sx) {
              const size_t i = tile.index(x * scale + sx, y * scale + sy);
              sum += buf.color[i];
              marked = marked || buf.stub[i] != 0;
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
