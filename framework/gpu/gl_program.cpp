#define GL_GLEXT_PROTOTYPES 1
#include "gpu/gl_program.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <stdexcept>
#include <vector>

namespace ll::gpu {

namespace {

unsigned compile(GLenum type, const std::string& source) {
  const unsigned shader = glCreateShader(type);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(std::max(length, 1)));
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    // A shader bug is ours, not the user's: an internal error with the driver's words.
    throw std::runtime_error(std::string(type == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                             " shader does not compile: " + log.data());
  }
  return shader;
}

}  // namespace

GlProgram::GlProgram(const std::string& vertexSource, const std::string& fragmentSource) {
  const unsigned vs = compile(GL_VERTEX_SHADER, vertexSource);
  const unsigned fs = compile(GL_FRAGMENT_SHADER, fragmentSource);
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    std::vector<char> log(4096);
    glGetProgramInfoLog(id_, static_cast<GLsizei>(log.size()), nullptr, log.data());
    glDeleteProgram(id_);
    throw std::runtime_error(std::string("shader program does not link: ") + log.data());
  }
}

GlProgram::~GlProgram() {
  glDeleteProgram(id_);
}

int GlProgram::uniform(const char* name) const {
  return glGetUniformLocation(id_, name);
}

}  // namespace ll::gpu
