// The fixed-function part of the pipeline (framework code): vertex stage,
// homogeneous near-plane clipping, viewport transform, triangle setup with
// edge functions and the top-left fill rule (A1.2), perspective-correct
// interpolation, z-buffer (A1.3), fragment stage and supersampling with a box
// filter. Vertex stage and setup run in parallel chunks of triangles;
// triangles are binned to 16x16-pixel tiles; tiles run in parallel (oneTBB),
// each owning its pixels and drawing its triangles in submission order, so
// the image does not depend on the thread count. Within a tile, a visibility
// pass (coverage + z-buffer) runs first and the fragment stage then shades
// each sample's surviving fragment once -- the picture of drawing every
// fragment in order (ties keep the earlier triangle) without paying for the
// hidden ones, as tile-based GPUs do.
#pragma once

#include <atomic>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/math.h"
#include "render/frame_buffer.h"
#include "render/student_task.h"
#include "shader.h"

namespace ll::a1 {

struct DrawCall {
  int firstVertex = 0, vertexCount = 0;  // non-indexed triangles: 3 vertices each
  int object = 0;
};

struct ScreenTriangle;  // rasterizer.cpp

// Buffers kept from frame to frame: their capacity is reused, so a steady
// frame allocates nothing large. Owned by the caller, used by one frame at a
// time; its contents are the rasterizer's business.
struct RasterWorkspace {
  RasterWorkspace();
  ~RasterWorkspace();
  std::vector<std::vector<ScreenTriangle>> chunks;  // setup output per chunk of input triangles
  std::vector<std::vector<uint32_t>> bins;          // per tile: triangle references in submission order
};

struct RasterSettings {
  int width = 0, height = 0;  // pixels of fb
  int scale = 1;              // scale x scale ordered supersamples per pixel, box-filtered
  Rgb background{0.0f};
  TaskLog* taskLog = nullptr;  // installed on every worker (student stubs report here)
};

// Adds one sample per pixel of fb (the box-filtered supersamples); pixels
// whose computation went through a student stub are marked. Returns early
// (leaving pixels unwritten) when `cancel` becomes true. Returns the number
// of non-finite fragment colours, which were drawn as 0.
uint64_t rasterize(const Shader& shader, const std::vector<DrawCall>& draws, const RasterSettings& settings,
                   FrameBuffer& fb, const std::atomic<bool>& cancel);
// The same, reusing `workspace`'s buffers (what an interactive renderer calls per frame).
uint64_t rasterize(RasterWorkspace& workspace, const Shader& shader, const std::vector<DrawCall>& draws,
                   const RasterSettings& settings, FrameBuffer& fb, const std::atomic<bool>& cancel);

}  // namespace ll::a1
