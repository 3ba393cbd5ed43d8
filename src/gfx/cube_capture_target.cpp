#include "gfx/cube_capture_target.h"

#include <algorithm>

namespace reflect {
namespace {

TextureHandle createColourCube(const CaptureFormat& format, int size) {
  TextureHandle texture(genTexture());
  glBindTexture(GL_TEXTURE_CUBE_MAP, texture.id());
  for (GLenum face = 0; face < 6; ++face) {
    if (format.halfFloat) {
      glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA16F, size, size, 0, GL_RGBA,
                   GL_HALF_FLOAT, nullptr);
    } else {
      glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA8, size, size, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, nullptr);
    }
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER,
                  format.mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  if (format.mipmaps) glGenerateMipmap(GL_TEXTURE_CUBE_MAP);  // allocates the chain
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  return texture;
}

// Integer textures are read with texelFetch only, and must not be filtered.
TextureHandle createDepthChain(int size, int levels) {
  TextureHandle texture(genTexture());
  glBindTexture(GL_TEXTURE_2D_ARRAY, texture.id());
  glTexStorage3D(GL_TEXTURE_2D_ARRAY, levels, GL_RG16UI, size, size, 6);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, levels - 1);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  return texture;
}

}  // namespace

Result<CubeCaptureTarget> CubeCaptureTarget::create(const CaptureFormat& format) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &maxSize);
  CubeCaptureTarget t;
  t.format_ = format;
  t.format_.faceSize = std::clamp(format.faceSize, 1, std::max(1, static_cast<int>(maxSize)));
  t.format_.layers = format.depthChain ? std::clamp(format.layers, 1, 2) : 1;
  const int size = t.format_.faceSize;
  while ((size >> t.topLevel_) > 1) ++t.topLevel_;

  for (int layer = 0; layer < t.format_.layers; ++layer) {
    t.colour_[static_cast<size_t>(layer)] = createColourCube(t.format_, size);
    if (format.depthChain) {
      t.depths_[static_cast<size_t>(layer)] = createDepthChain(size, t.topLevel_ + 1);
    }
  }

  if (t.format_.layers == 2) {
    t.backs_ = TextureHandle(genTexture());
    glBindTexture(GL_TEXTURE_2D_ARRAY, t.backs_.id());
    glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_R16UI, size, size, 6);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  }

  t.depth_ = RenderbufferHandle(genRenderbuffer());
  glBindRenderbuffer(GL_RENDERBUFFER, t.depth_.id());
  glRenderbufferStorage(GL_RENDERBUFFER,
                        format.depthBits <= 16 ? GL_DEPTH_COMPONENT16 : GL_DEPTH_COMPONENT24, size,
                        size);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);

  t.framebuffer_ = FramebufferHandle(genFramebuffer());
  glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth_.id());
  t.bindFace(0, 0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (format.depthChain) t.reduceFramebuffer_ = FramebufferHandle(genFramebuffer());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    return Result<CubeCaptureTarget>::failure(
        std::string("cube capture framebuffer incomplete") +
        (format.halfFloat ? " (RGBA16F faces need EXT_color_buffer_float or _half_float)" : "") +
        " (status " + std::to_string(status) + ")");
  }
  if (!checkGlError("create cube capture target")) {
    return Result<CubeCaptureTarget>::failure("GL error while creating the cube capture target");
  }
  return t;
}

void CubeCaptureTarget::bindFace(int face, int layer) const {
  const size_t l = static_cast<size_t>(layer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                         GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(face),
                         colour_[l].id(), 0);
  if (format_.depthChain) {
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, depths_[l].id(), 0, face);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, buffers);
  }
  glViewport(0, 0, format_.faceSize, format_.faceSize);
}

void CubeCaptureTarget::clearFace(const float colour[3], float alpha,
                                  const unsigned codes[2]) const {
  const GLfloat rgba[4] = {colour[0], colour[1], colour[2], alpha};
  glClearBufferfv(GL_COLOR, 0, rgba);
  if (format_.depthChain) {
    const GLuint values[4] = {codes[0], codes[1], 0, 0};
    glClearBufferuiv(GL_COLOR, 1, values);
  }
  const GLfloat far = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &far);
}

void CubeCaptureTarget::bindBackPass(int face) const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, backs_.id(), 0, face);
  const GLenum buffers[2] = {GL_NONE, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, buffers);
  glViewport(0, 0, format_.faceSize, format_.faceSize);
  const GLuint none[4] = {0, 0, 0, 0};
  glClearBufferuiv(GL_COLOR, 1, none);
  const GLfloat near = 0.0f;
  glClearBufferfv(GL_DEPTH, 0, &near);
  glDepthFunc(GL_GREATER);
}

void CubeCaptureTarget::endBackPass(int face, GLuint merge, GLint mergeLayer) const {
  glDepthFunc(GL_LESS);
  glBindFramebuffer(GL_FRAMEBUFFER, reduceFramebuffer_.id());
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, depths_[0].id(), 0, face);
  glViewport(0, 0, format_.faceSize, format_.faceSize);
  glUseProgram(merge);
  glUniform1i(mergeLayer, face);
  glActiveTexture(GL_TEXTURE0);  // the merge's u_backs
  glBindTexture(GL_TEXTURE_2D_ARRAY, backs_.id());
  glDisable(GL_DEPTH_TEST);
  glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_FALSE);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_DEPTH_TEST);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
}

void CubeCaptureTarget::reduceDepths(int face, int layer, GLuint reduce, GLint sourceSize,
                                     GLint sourceLayer) const {
  if (!format_.depthChain) return;
  const GLuint chain = depths_[static_cast<size_t>(layer)].id();
  glBindFramebuffer(GL_FRAMEBUFFER, reduceFramebuffer_.id());
  glUseProgram(reduce);
  glUniform1i(sourceLayer, face);
  glActiveTexture(GL_TEXTURE0);  // the reduction's u_source
  glBindTexture(GL_TEXTURE_2D_ARRAY, chain);
  glDisable(GL_DEPTH_TEST);
  for (int level = 1; level <= topLevel_; ++level) {
    // The level below is the only one the program may read: the one written is outside the
    // sampled range, so this is no feedback loop (WebGL checks).
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BASE_LEVEL, level - 1);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, level - 1);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, chain, level, face);
    const int below = std::max(format_.faceSize >> (level - 1), 1);
    const int size = std::max(format_.faceSize >> level, 1);
    glUniform2i(sourceSize, below, below);
    glViewport(0, 0, size, size);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, topLevel_);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  glEnable(GL_DEPTH_TEST);
}

void CubeCaptureTarget::finish() const {
  if (!format_.mipmaps) return;
  for (int layer = 0; layer < format_.layers; ++layer) {
    glBindTexture(GL_TEXTURE_CUBE_MAP, colour_[static_cast<size_t>(layer)].id());
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
  }
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
}

void CubeCaptureTarget::abandon() {
  for (TextureHandle& t : colour_) t.abandon();
  for (TextureHandle& t : depths_) t.abandon();
  backs_.abandon();
  depth_.abandon();
  framebuffer_.abandon();
  reduceFramebuffer_.abandon();
}

}  // namespace reflect
