// Move-only ownership of one GL object name: deleted exactly once, never copied, and never
// deleted through a context that is gone.
#pragma once

#include <utility>

#include "gfx/gl.h"

namespace reflect {

// GL objects owned by handles right now, for leak checks (a long run must not grow it).
inline long gLiveGlObjects = 0;

// Which GL context the names belong to. A lost context takes every name with it, so each handle
// remembers the generation it was made in and, once that has passed, forgets its name without
// calling GL: no class keeps a list of its handles to abandon.
inline unsigned gGlContextGeneration = 1;
// The platform calls this when the context is lost, before the owners are destroyed.
inline void markGlContextLost() {
  ++gGlContextGeneration;
}

template <void (*Delete)(GLuint)>
class GlHandle {
 public:
  GlHandle() = default;
  explicit GlHandle(GLuint id) : id_(id), generation_(gGlContextGeneration) {
    if (id_ != 0) ++gLiveGlObjects;
  }
  ~GlHandle() { reset(); }
  GlHandle(const GlHandle&) = delete;
  GlHandle& operator=(const GlHandle&) = delete;
  GlHandle(GlHandle&& other) noexcept
      : id_(std::exchange(other.id_, 0)), generation_(other.generation_) {}
  GlHandle& operator=(GlHandle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
      generation_ = other.generation_;
    }
    return *this;
  }

  // 0 once the context that made the name is gone: the name means nothing any more.
  GLuint id() const { return alive() ? id_ : 0; }
  explicit operator bool() const { return id() != 0; }
  void reset() {
    if (id_ != 0) {
      if (alive()) Delete(id_);
      --gLiveGlObjects;
    }
    id_ = 0;
  }

 private:
  bool alive() const { return generation_ == gGlContextGeneration; }

  GLuint id_ = 0;
  unsigned generation_ = 0;
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
using QueryHandle = GlHandle<deleteOne<glDeleteQueries>>;
using SamplerHandle = GlHandle<deleteOne<glDeleteSamplers>>;
using TransformFeedbackHandle = GlHandle<deleteOne<glDeleteTransformFeedbacks>>;
using ProgramHandle = GlHandle<glDeleteProgram>;
using ShaderHandle = GlHandle<glDeleteShader>;

constexpr auto genBuffer = generateOne<glGenBuffers>;
constexpr auto genVertexArray = generateOne<glGenVertexArrays>;
constexpr auto genTexture = generateOne<glGenTextures>;
constexpr auto genFramebuffer = generateOne<glGenFramebuffers>;
constexpr auto genRenderbuffer = generateOne<glGenRenderbuffers>;
constexpr auto genQuery = generateOne<glGenQueries>;

// A sampler object filtering by `minFilter` and `magFilter` (the rest GL's defaults).
inline SamplerHandle filteredSampler(GLint minFilter, GLint magFilter) {
  SamplerHandle sampler(generateOne<glGenSamplers>());
  glSamplerParameteri(sampler.id(), GL_TEXTURE_MIN_FILTER, minFilter);
  glSamplerParameteri(sampler.id(), GL_TEXTURE_MAG_FILTER, magFilter);
  return sampler;
}

}  // namespace reflect
