// No NaN or Inf reaches a pixel of the techniques that do not go through
// PixelTechnique (render_pipeline_test.cpp checks that one): the software
// rasterizer behind blinn-phong and radiosity-raster counts every non-finite
// fragment colour and draws it as 0.
#include <atomic>
#include <limits>

#include <gtest/gtest.h>

#include "rasterizer.h"
#include "render/frame_buffer.h"
#include "shader.h"

namespace ll {
namespace {

// Two quads side by side in clip space, x in [-1, 0] (object 0) and [0, 1] (object 1): object 0's
// fragments are NaN, object 1's are 0.5.
class HalfNaNShader final : public a1::Shader {
 public:
  Vec4 vertex(int index, int object, a1::Varyings& out) const override {
    const Vec2 corners[6] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};  // two triangles, counter-clockwise
    const Vec2 c = corners[index % 6];
    out.position = Vec3(c, 0.0f);
    return Vec4(static_cast<float>(object) - 1.0f + c.x, 2.0f * c.y - 1.0f, 0.0f, 1.0f);
  }
  Rgb fragment(const a1::Fragment& f) const override {
    return f.object == 0 ? Rgb(std::numeric_limits<float>::quiet_NaN()) : Rgb(0.5f);
  }
};

TEST(Numerics_NonFinite, TheRasterizerCountsNaNFragmentsAndDrawsThemAsZero) {
  const HalfNaNShader shader;
  a1::RasterSettings s;
  s.width = 8;
  s.height = 4;
  s.scale = 2;  // 2 x 2 samples per pixel
  FrameBuffer fb(s.width, s.height);
  const std::atomic<bool> cancel{false};
  const uint64_t nonFinite = a1::rasterize(shader, {a1::DrawCall{0, 6, 0}, a1::DrawCall{0, 6, 1}}, s, fb, cancel);
  EXPECT_EQ(nonFinite, 4u * 4u * 4u);  // the left half: 4 x 4 pixels of 4 samples, each once
  const Image image = fb.resolve(false);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) EXPECT_EQ(image.at(x, y), Rgb(x < 4 ? 0.0f : 0.5f)) << x << "," << y;
}

}  // namespace
}  // namespace ll
