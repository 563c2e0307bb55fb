// A linked GLSL program from vertex and fragment source, with compile and
// link logs turned into one-line errors. Requires a current GL 3.3 context.
#pragma once

#include <string>

namespace ll::gpu {

class GlProgram {
 public:
  GlProgram(const std::string& vertexSource, const std::string& fragmentSource);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  unsigned id() const { return id_; }
  int uniform(const char* name) const;  // -1 if the shader does not use it

 private:
  unsigned id_ = 0;
};

}  // namespace ll::gpu
