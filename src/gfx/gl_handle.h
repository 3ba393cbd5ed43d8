// Move-only ownership of one GL object name: deleted exactly once, never copied.
#pragma once

#include <utility>

#include "gfx/gl.h"

namespace reflect {

// GL objects owned by handles right now, for leak checks (a long run must not grow it).
inline long gLiveGlObjects = 0;

template <void (*Delete)(GLuint)>
class GlHandle {
 public:
  GlHandle() = default;
  explicit GlHandle(GLuint id) : id_(id) {
    if (id_ != 0) ++gLiveGlObjects;
  }
  ~GlHandle() { reset(); }
  GlHandle(const GlHandle&) = delete;
  GlHandle& operator=(const GlHandle&) = delete;
  GlHandle(GlHandle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlHandle& operator=(GlHandle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_ != 0) {
      Delete(id_);
      --gLiveGlObjects;
    }
    id_ = 0;
  }
  // After a lost context the names are already gone: forget them without calling GL.
  void abandon() {
    if (id_ != 0) --gLiveGlObjects;
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

namespace gl_delete {
inline void buffer(GLuint id) {
  glDeleteBuffers(1, &id);
}
inline void vertexArray(GLuint id) {
  glDeleteVertexArrays(1, &id);
}
inline void texture(GLuint id) {
  glDeleteTextures(1, &id);
}
inline void framebuffer(GLuint id) {
  glDeleteFramebuffers(1, &id);
}
inline void renderbuffer(GLuint id) {
  glDeleteRenderbuffers(1, &id);
}
inline void program(GLuint id) {
  glDeleteProgram(id);
}
inline void shader(GLuint id) {
  glDeleteShader(id);
}
}  // namespace gl_delete

using BufferHandle = GlHandle<gl_delete::buffer>;
using VertexArrayHandle = GlHandle<gl_delete::vertexArray>;
using TextureHandle = GlHandle<gl_delete::texture>;
using FramebufferHandle = GlHandle<gl_delete::framebuffer>;
using RenderbufferHandle = GlHandle<gl_delete::renderbuffer>;
using ProgramHandle = GlHandle<gl_delete::program>;
using ShaderHandle = GlHandle<gl_delete::shader>;

inline GLuint genBuffer() {
  GLuint id = 0;
  glGenBuffers(1, &id);
  return id;
}
inline GLuint genVertexArray() {
  GLuint id = 0;
  glGenVertexArrays(1, &id);
  return id;
}
inline GLuint genTexture() {
  GLuint id = 0;
  glGenTextures(1, &id);
  return id;
}
inline GLuint genFramebuffer() {
  GLuint id = 0;
  glGenFramebuffers(1, &id);
  return id;
}
inline GLuint genRenderbuffer() {
  GLuint id = 0;
  glGenRenderbuffers(1, &id);
  return id;
}

}  // namespace reflect
