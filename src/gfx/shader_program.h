// A linked GLSL ES 3.00 program built from two embedded shader files.
#pragma once

#include <string>
#include <vector>

#include "core/result.h"
#include "gfx/gl_handle.h"

namespace reflect {

// Vertex attribute locations shared by every shader (layout(location = N) in mesh.vert).
inline constexpr GLuint kAttribPosition = 0;
inline constexpr GLuint kAttribNormal = 1;
inline constexpr GLuint kAttribAmbientParallax = 2;  // mesh.vert's, probe-lit objects only

class ShaderProgram {
 public:
  // Prepends "#version 300 es" and the float precision in one place (fragment shaders mediump
  // when asked), and replaces each line `#include "file.glsl"` with that embedded file (once per
  // shader). Failure carries the stage, the file name and the driver's log.
  // `defines` ("#define NAME VALUE\n" lines) follow the prelude in both shaders.
  static Result<ShaderProgram> build(const std::string& vertexFile, const std::string& fragmentFile,
                                     bool mediump = false, const std::string& defines = "",
                                     const std::vector<std::string>& feedback = {});
  // The same from GLSL text (without #version); the names label messages. For tools and tests.
  static Result<ShaderProgram> buildFromSource(const std::string& vertexName,
                                               const char* vertexSource,
                                               const std::string& fragmentName,
                                               const char* fragmentSource, bool mediump = false,
                                               const std::string& defines = "",
                                               const std::vector<std::string>& feedback = {});

  GLuint id() const { return program_.id(); }
  // -1 (and a message on stderr) for a uniform the program does not have.
  GLint uniform(const char* name) const;
  // -1 without a message: for uniforms a shader may legitimately optimise away.
  GLint optionalUniform(const char* name) const {
    return glGetUniformLocation(program_.id(), name);
  }

 private:
  ProgramHandle program_;
  std::string label_;
};

}  // namespace reflect
