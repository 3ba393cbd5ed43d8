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

// GL's glDelete*/glGen* work on arrays of names; a handle owns one.
template <void (*DeleteNames)(GLsizei, const GLuint*)>
void deleteOne(GLuint id) {
  DeleteNames(1, &id);
}
template <void (*GenerateNames)(GLsizei, GLuint*)>
GLuint generateOne() {
  GLuint id = 0;
  GenerateNames(1, &id);
  return id;
}

using BufferHandle = GlHandle<deleteOne<glDeleteBuffers>>;
using VertexArrayHandle = GlHandle<deleteOne<glDeleteVertexArrays>>;
using TextureHandle = GlHandle<deleteOne<glDeleteTextures>>;
using FramebufferHandle = GlHandle<deleteOne<glDeleteFramebuffers>>;
using RenderbufferHandle = GlHandle<deleteOne<glDeleteRenderbuffers>>;
using ProgramHandle = GlHandle<glDeleteProgram>;
using ShaderHandle = GlHandle<glDeleteShader>;

constexpr auto genBuffer = generateOne<glGenBuffers>;
constexpr auto genVertexArray = generateOne<glGenVertexArrays>;
constexpr auto genTexture = generateOne<glGenTextures>;
constexpr auto genFramebuffer = generateOne<glGenFramebuffers>;
constexpr auto genRenderbuffer = generateOne<glGenRenderbuffers>;

}  // namespace reflect
