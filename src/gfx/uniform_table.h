// A program's uniforms as a typed table: each is declared once, with its GLSL name and the C++
// type it takes, and registers itself in the table that locates them all by name. Nothing is
// filled by position, a value of the wrong type does not compile, and a test can ask a program
// for the active uniforms no table entry sets (a uniform the shader reads and C++ never writes).
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "gfx/shader_program.h"

namespace reflect {

class UniformSlot;

// The uniforms registered by their declarations. Not copyable or movable (the entries point into
// their owner): hold a table's owner by unique_ptr where it must move.
class UniformTable {
 public:
  UniformTable() = default;
  UniformTable(const UniformTable&) = delete;
  UniformTable& operator=(const UniformTable&) = delete;

  // Finds every entry in `program` (-1, which GL ignores, where the variant does not use it).
  void locate(const ShaderProgram& program);
  // The active uniforms of `program` that no entry names ("u_faceAxis" for "u_faceAxis[0]").
  std::vector<std::string> unlisted(GLuint program) const;

 private:
  friend class UniformSlot;
  std::vector<UniformSlot*> entries_;
};

class UniformSlot {
 public:
  UniformSlot(UniformTable& table, const char* name) : name_(name) {
    table.entries_.push_back(this);
  }
  UniformSlot(const UniformSlot&) = delete;
  UniformSlot& operator=(const UniformSlot&) = delete;
  const char* name() const { return name_; }
  GLint location() const { return location_; }

 private:
  friend class UniformTable;
  const char* name_;
  GLint location_ = -1;
};

// What each C++ type sets: the GLSL type of the same name (bool as an int 0 or 1).
inline void setUniform(GLint at, int value) {
  glUniform1i(at, value);
}
inline void setUniform(GLint at, bool value) {
  glUniform1i(at, value ? 1 : 0);
}
inline void setUniform(GLint at, float value) {
  glUniform1f(at, value);
}
inline void setUniform(GLint at, const glm::vec2& value) {
  glUniform2f(at, value.x, value.y);
}
inline void setUniform(GLint at, const glm::ivec2& value) {
  glUniform2i(at, value.x, value.y);
}
inline void setUniform(GLint at, const glm::vec3& value) {
  glUniform3fv(at, 1, glm::value_ptr(value));
}
inline void setUniform(GLint at, const glm::vec4& value) {
  glUniform4fv(at, 1, glm::value_ptr(value));
}
inline void setUniform(GLint at, const glm::mat3& value) {
  glUniformMatrix3fv(at, 1, GL_FALSE, glm::value_ptr(value));
}
inline void setUniform(GLint at, const glm::mat4& value) {
  glUniformMatrix4fv(at, 1, GL_FALSE, glm::value_ptr(value));
}

template <typename T>
class Uniform : public UniformSlot {
 public:
  using UniformSlot::UniformSlot;
  // Into the program in use.
  void set(const T& value) const { setUniform(location(), value); }
};

// An array uniform (`uniform vec3 u_faceAxis[6]`), set from its first element on.
template <typename T>
class UniformArray : public UniformSlot {
 public:
  using UniformSlot::UniformSlot;
  void set(const T* values, size_t count) const;
};

template <>
inline void UniformArray<glm::vec3>::set(const glm::vec3* values, size_t count) const {
  glUniform3fv(location(), static_cast<GLsizei>(count), glm::value_ptr(values[0]));
}
template <>
inline void UniformArray<glm::vec4>::set(const glm::vec4* values, size_t count) const {
  glUniform4fv(location(), static_cast<GLsizei>(count), glm::value_ptr(values[0]));
}

// A program built with its table of uniforms, located: the one way the renderer's programs are
// made. `Uniforms` is a UniformTable of entries; held by pointer, as a table does not move.
template <typename Uniforms>
struct TabledProgram {
  ShaderProgram program;
  std::unique_ptr<Uniforms> uniforms;

  // ShaderProgram::build's arguments; failure carries its message (the file and the log).
  static Result<TabledProgram> build(const std::string& vertexFile, const std::string& fragmentFile,
                                     bool mediump = false, const std::string& defines = "") {
    Result<ShaderProgram> built = ShaderProgram::build(vertexFile, fragmentFile, mediump, defines);
    if (!built) return Result<TabledProgram>::failure(built.error());
    TabledProgram p;
    p.uniforms = std::make_unique<Uniforms>();
    p.uniforms->locate(built.value());
    p.program = built.take();
    return p;
  }
  GLuint id() const { return program.id(); }
  const Uniforms& u() const { return *uniforms; }
  // The active uniforms this program's table does not set (for tests).
  std::vector<std::string> unlisted() const { return uniforms->unlisted(program.id()); }
};

// Builds a pass's program of type `Program` (a TabledProgram) and hands it to `make`, which
// returns the pass that owns it; a failure to build is the result instead.
template <typename Program, typename Make>
auto withBuiltProgram(const std::string& vertexFile, const std::string& fragmentFile, Make make)
    -> Result<decltype(make(std::declval<Program>()))> {
  using Out = Result<decltype(make(std::declval<Program>()))>;
  Result<Program> program = Program::build(vertexFile, fragmentFile);
  if (!program) return Out::failure(program.error());
  return make(program.take());
}

}  // namespace reflect
