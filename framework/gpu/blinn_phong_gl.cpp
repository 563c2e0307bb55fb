// Technique `blinn-phong-gl`: the lecture's local shading model on the GPU,
// the twin of the software rasterizer `blinn-phong` (assignment 1), so the
// same equation can be wiped and diffed CPU against GPU in the GUI:
//   L = Le + ka*Ia + sum over lights [ kd*(I/r^2)*max(0, n.l) + ks*(I/r^2)*max(0, n.h)^p ]
// Point lights as declared; directional lights without 1/r^2; each area
// light as `light_samples` point lights on a fixed stratified grid, each of
// intensity I = Le * (A / N) * max(0, n_light . -l) / pi (the convention of
// ray casting, so the three agree where no shadows fall). No shadows: a
// rasterizer has none. Renders into a float framebuffer on the offscreen
// context (gpu/offscreen_gl.h), supersampled 1x, 2x2 or 4x4, and reads the
// box-filtered pixels back into the frame buffer like any other technique.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "gpu/gl_program.h"
#include "gpu/offscreen_gl.h"
#include "render/raster_scene.h"
#include "render/technique.h"

namespace ll {

namespace {

constexpr int kMaxLights =
    64;  // 3 x 64 vec4 uniforms: within GL 3.3's minimum of 1024 components per stage

// The lights' diffuse and specular sums D and S at a point, shared by the
// vertex shader (Gouraud) and the fragment shader (flat, Phong), so a texture
// can still scale kd per fragment: L = Le + ka*Ia + kd*D + ks*S.
const char* kLighting = R"(
uniform vec3 uEye;
uniform int uLightCount;
uniform vec4 uLightPosition[64];   // w: 1 point, 0 directional (xyz = towards the light), 2 area sample
uniform vec3 uLightNormal[64];     // area samples: the emitting side
uniform vec3 uLightIntensity[64];
uniform float uShininess;
void lightSums(vec3 position, vec3 n, out vec3 D, out vec3 S) {
  vec3 v = normalize(uEye - position);
  if (dot(n, v) < 0.0) n = -n;  // two-sided, as the ray tracers shade
  D = vec3(0.0);
  S = vec3(0.0);
  for (int i = 0; i < uLightCount; ++i) {
    vec3 l;
    vec3 I = uLightIntensity[i];
    if (uLightPosition[i].w == 0.0) {
      l = normalize(uLightPosition[i].xyz);
    } else {
      vec3 d = uLightPosition[i].xyz - position;
      float r2 = max(dot(d, d), 1e-12);
      l = d * inversesqrt(r2);
      I /= r2;
      if (uLightPosition[i].w == 2.0) I *= max(0.0, dot(uLightNormal[i], -l)) / 3.14159265358979;
    }
    float ndotl = max(0.0, dot(n, l));
    D += I * ndotl;
    if (ndotl > 0.0) S += I * pow(max(0.0, dot(n, normalize(l + v))), uShininess);
  }
}
)";

const std::string kVertexShader = std::string(R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
uniform mat4 uViewProjection;
uniform int uShading;  // 0 flat, 1 gouraud, 2 phong
out vec3 vPosition;
out vec3 vNormal;
out vec2 vUv;
out vec3 vD;
out vec3 vS;
)") + kLighting + R"(
void main() {
  vPosition = aPosition;
  vNormal = aNormal;
  vUv = aUv;
  vD = vec3(0.0);
  vS = vec3(0.0);
  if (uShading == 1) lightSums(aPosition, normalize(aNormal), vD, vS);
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
)";

const std::string kFragmentShader = std::string(R"(#version 330 core
in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv;
in vec3 vD;
in vec3 vS;
out vec4 outColor;
uniform int uShading;
uniform vec3 uKa, uKd, uKs, uEmission, uAmbient;
uniform int uTextureKind;  // 0 none, 1 image (multiplies kd), 2 checker (replaces kd)
uniform sampler2D uTexture;
uniform vec2 uSquares;
uniform vec3 uColorA, uColorB;
)") + kLighting + R"(
void main() {
  vec3 D = vD, S = vS;
  if (uShading == 0) lightSums(vPosition, normalize(cross(dFdx(vPosition), dFdy(vPosition))), D, S);
  if (uShading == 2) lightSums(vPosition, normalize(vNormal), D, S);
  vec3 kd = uKd;
  if (uTextureKind == 1) kd *= texture(uTexture, vUv).rgb;
  if (uTextureKind == 2) {
    ivec2 c = ivec2(floor(vUv * uSquares));
    kd = ((c.x + c.y) & 1) == 0 ? uColorA : uColorB;
  }
  outColor = vec4(uEmission + uKa * uAmbient + kd * D + uKs * S, 1.0);
}
)";

// The scene's lights as the shader's point-like lights (area lights as n x n grids).
std::vector<RasterLight> lightsOf(const Scene& scene, int areaSamples) {
  std::vector<RasterLight> lights = rasterLights(scene, areaSamples);
  if (lights.size() > static_cast<size_t>(kMaxLights))
    throwUserError("blinn-phong-gl: the scene needs " + std::to_string(lights.size()) +
                   " point lights (at most " + std::to_string(kMaxLights) +
                   "); lower light_samples");
  return lights;
}

class BlinnPhongGl final : public Technique {
 public:
  int passCount(const RenderContext&) const override { return 1; }

  void renderPass(const RenderContext& ctx, int pass, FrameBuffer& fb, WorkCounters& counters,
                  const std::atomic<bool>& cancel) override {
    (void)pass;
    const ParamSet& p = ctx.params;
    const int scale = p.getChoice("samples") == "16" ? 4 : p.getChoice("samples") == "4" ? 2 : 1;
    const Camera camera = renderCamera(ctx.scene, ctx.settings);
    const int w = camera.width * scale, h = camera.height * scale;
    const RasterMesh mesh = buildRasterMesh(ctx.scene, p.getInt("sphere_segments"));
    const std::vector<RasterLight> lights = lightsOf(ctx.scene, p.getInt("light_samples"));
    if (cancel) return;

    const gpu::OffscreenGl::Lease lease;
    const gpu::GlProgram program(kVertexShader, kFragmentShader);
    GLuint fbo = 0, color = 0, depth = 0, vao = 0, vbo = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glGenTextures(1, &color);
    glBindTexture(GL_TEXTURE_2D, color);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throwUserError("blinn-phong-gl: the GPU cannot make a " + std::to_string(w) + "x" +
                     std::to_string(h) + " float framebuffer; lower samples or the size");

    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(RasterVertex)),
                 mesh.vertices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(RasterVertex),
                          reinterpret_cast<void*>(offsetof(RasterVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(RasterVertex),
                          reinterpret_cast<void*>(offsetof(RasterVertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(RasterVertex),
                          reinterpret_cast<void*>(offsetof(RasterVertex, uv)));

    // Camera: the scene's pinhole; depth range from the scene's bounds.
    const DepthRange clip = rasterDepthRange(ctx.scene, camera);
    const glm::mat4 view = glm::lookAt(camera.eye, camera.target, camera.up);
    const glm::mat4 projection =
        glm::perspective(glm::radians(camera.fovYDeg), camera.aspect(), clip.near, clip.far);
    const glm::mat4 viewProjection = projection * view;

    glViewport(0, 0, w, h);
    glClearColor(ctx.scene.background.r, ctx.scene.background.g, ctx.scene.background.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glUseProgram(program.id());
    glUniformMatrix4fv(program.uniform("uViewProjection"), 1, GL_FALSE,
                       glm::value_ptr(viewProjection));
    glUniform3fv(program.uniform("uEye"), 1, glm::value_ptr(camera.eye));
    const std::string shading = p.getChoice("shading");
    glUniform1i(program.uniform("uShading"), shading == "flat" ? 0 : shading == "gouraud" ? 1 : 2);
    glUniform1i(program.uniform("uLightCount"), static_cast<GLint>(lights.size()));
    for (size_t i = 0; i < lights.size(); ++i) {
      const std::string idx = "[" + std::to_string(i) + "]";
      const glm::vec4 position(lights[i].position, static_cast<float>(lights[i].kind));  // w: the kind
      glUniform4fv(program.uniform(("uLightPosition" + idx).c_str()), 1, glm::value_ptr(position));
      glUniform3fv(program.uniform(("uLightNormal" + idx).c_str()), 1,
                   glm::value_ptr(lights[i].normal));
      glUniform3fv(program.uniform(("uLightIntensity" + idx).c_str()), 1,
                   glm::value_ptr(lights[i].intensity));
    }
    glUniform3fv(program.uniform("uAmbient"), 1, glm::value_ptr(ctx.scene.ambient));
    glUniform1i(program.uniform("uTexture"), 0);

    const std::string filter = p.getChoice("filter");
    std::vector<GLuint> textures;
    for (size_t o = 0; o < ctx.scene.objects.size(); ++o) {
      const Material& m = ctx.scene.materials[ctx.scene.objects[o].material];
      glUniform3fv(program.uniform("uKa"), 1, glm::value_ptr(m.ka));
      glUniform3fv(program.uniform("uKd"), 1, glm::value_ptr(m.kd));
      glUniform3fv(program.uniform("uKs"), 1, glm::value_ptr(m.ks));
      glUniform3fv(program.uniform("uEmission"), 1, glm::value_ptr(m.emission));
      glUniform1f(program.uniform("uShininess"), m.shininess);
      const int kind = m.texture.kind == Texture::Kind::Image     ? 1
                       : m.texture.kind == Texture::Kind::Checker ? 2
                                                                  : 0;
      glUniform1i(program.uniform("uTextureKind"), kind);
      if (kind == 2) {
        glUniform2fv(program.uniform("uSquares"), 1, glm::value_ptr(m.texture.squares));
        glUniform3fv(program.uniform("uColorA"), 1, glm::value_ptr(m.texture.colorA));
        glUniform3fv(program.uniform("uColorB"), 1, glm::value_ptr(m.texture.colorB));
      }
      if (kind == 1) {
        const Image& img = *m.texture.image;
        // Image rows go top-down; GL's t = 0 is the bottom row, as the scene's v = 0 is.
        std::vector<Rgb> flipped(img.pixelCount());
        for (int y = 0; y < img.height(); ++y)
          for (int x = 0; x < img.width(); ++x)
            flipped[static_cast<size_t>(img.height() - 1 - y) * img.width() + x] = img.at(x, y);
        GLuint tex = 0;
        glGenTextures(1, &tex);
        textures.push_back(tex);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, img.width(), img.height(), 0, GL_RGB, GL_FLOAT,
                     flipped.data());
        glGenerateMipmap(GL_TEXTURE_2D);
        const GLint minFilter = filter == "nearest"    ? GL_NEAREST
                                : filter == "bilinear" ? GL_LINEAR
                                                       : GL_LINEAR_MIPMAP_LINEAR;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, minFilter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER,
                        filter == "nearest" ? GL_NEAREST : GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
      }
      const auto [first, count] = mesh.ranges[o];
      if (count > 0) glDrawArrays(GL_TRIANGLES, first, count);
    }

    std::vector<float> pixels(static_cast<size_t>(w) * h * 4);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, pixels.data());
    glDeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
    glDeleteBuffers(1, &vbo);
    glDeleteVertexArrays(1, &vao);
    glDeleteRenderbuffers(1, &depth);
    glDeleteTextures(1, &color);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    if (cancel) return;

    // Box filter of each pixel's scale x scale samples; GL rows go bottom-up.
    const float norm = 1.0f / static_cast<float>(scale * scale);
    for (int y = 0; y < camera.height; ++y)
      for (int x = 0; x < camera.width; ++x) {
        Rgb sum(0.0f);
        for (int sy = 0; sy < scale; ++sy)
          for (int sx = 0; sx < scale; ++sx) {
            const size_t row = static_cast<size_t>(h - 1 - (y * scale + sy));
            const float* px =
                &pixels[(row * static_cast<size_t>(w) + static_cast<size_t>(x * scale + sx)) * 4];
            sum += Rgb(px[0], px[1], px[2]);
          }
        Rgb value = sum * norm;
        if (!isFinite(value)) {  // never a NaN in a pixel: counted and drawn as 0
          ++counters.nonFinite;
          value = Rgb(0.0f);
        }
        fb.add(x, y, value);
      }
  }
};

}  // namespace

TechniqueInfo blinnPhongGlTechnique() {
  return {"blinn-phong-gl",
          "the Blinn-Phong rasterizer on the GPU (OpenGL 3.3, GUI only): the twin of blinn-phong, "
          "to wipe and diff",
          EffectSet{Effect::DirectLighting, Effect::GlossyHighlights, Effect::Textures,
                    Effect::Emission},
          0,
          {ParamDecl::choice("shading", "phong", {"flat", "gouraud", "phong"},
                             "flat: one normal per triangle (from screen derivatives); gouraud: lit per "
                             "vertex and interpolated; phong: interpolated normals, lit per pixel"),
           ParamDecl::choice("samples", "1", {"1", "4", "16"},
                             "supersamples per pixel (ordered grid 1x1, 2x2, 4x4)"),
           ParamDecl::choice("filter", "trilinear", {"nearest", "bilinear", "trilinear"},
                             "texture filtering (trilinear uses mipmaps)"),
           ParamDecl::integer(
               "light_samples", 16, 1, 64,
               "point lights per area light (rounded to a square grid; at most 64 lights in all)"),
           ParamDecl::integer("sphere_segments", 48, 8, 256,
                              "tessellation of spheres around the equator")},
          []() -> std::unique_ptr<Technique> { return std::make_unique<BlinnPhongGl>(); },
          true};
}

}  // namespace ll
