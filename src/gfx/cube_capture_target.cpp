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
  if (format.mipmaps || format.boxChain) glGenerateMipmap(GL_TEXTURE_CUBE_MAP);  // the chain
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  return texture;
}

// Integer textures are read with texelFetch only, and must not be filtered.
void setIntegerFiltering(GLenum target) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

TextureHandle createFaceArray(GLenum format, int size) {
  TextureHandle texture(genTexture());
  glBindTexture(GL_TEXTURE_2D_ARRAY, texture.id());
  glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, format, size, size, 6);
  setIntegerFiltering(GL_TEXTURE_2D_ARRAY);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  return texture;
}

// Levels 0..top: the six faces' tiles side by side, P texels square at its base; (near, far) for
// each layer.
TextureHandle createPyramid(int top, int layers) {
  TextureHandle texture(genTexture());
  const int tile = 1 << top;
  glBindTexture(GL_TEXTURE_2D, texture.id());
  glTexStorage2D(GL_TEXTURE_2D, top + 1, layers == 2 ? GL_RGBA16UI : GL_RG16UI, 6 * tile, tile);
  setIntegerFiltering(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, 0);
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
  while ((1 << t.topLevel_) < size) ++t.topLevel_;

  for (int layer = 0; layer < t.format_.layers; ++layer) {
    const size_t l = static_cast<size_t>(layer);
    t.colour_[l] = createColourCube(t.format_, size);
    if (format.depthChain) t.faceDepths_[l] = createFaceArray(GL_RG16UI, size);
  }
  if (format.depthChain) t.pyramid_ = createPyramid(t.topLevel_, t.format_.layers);
  if (t.format_.layers == 2) t.backs_ = createFaceArray(GL_R16UI, size);

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
  if (format.depthChain) t.pyramidFramebuffer_ = FramebufferHandle(genFramebuffer());
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
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, faceDepths_[l].id(), 0, face);
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

void CubeCaptureTarget::endBackPass() {
  glDepthFunc(GL_LESS);
}

void CubeCaptureTarget::finish(const DepthPyramidPrograms& programs, unsigned faces) const {
  glDisable(GL_DEPTH_TEST);
  if (format_.depthChain && faces != 0) {
    glBindFramebuffer(GL_FRAMEBUFFER, pyramidFramebuffer_.id());
    const int baseTile = 1 << topLevel_;
    const bool two = format_.layers == 2;
    const GLuint pyramid = pyramid_.id();
    // Each level is drawn over the runs of consecutive faces to rebuild, one draw a run (one
    // draw a level when all six were captured). The programs find a texel's face from its
    // window position, which a viewport's offset keeps.
    const auto drawFaces = [faces](int tile) {
      for (int first = 0; first < 6;) {
        if (!(faces & (1u << first))) {
          ++first;
          continue;
        }
        int end = first + 1;
        while (end < 6 && (faces & (1u << end))) ++end;
        glViewport(first * tile, 0, (end - first) * tile, tile);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        first = end;
      }
    };
    // Level 0, from the faces' own layers and the backs.
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, pyramid, 0);
    glUseProgram(programs.first.id());
    programs.first.u().layers.set(format_.layers);
    programs.first.u().faceSize.set(format_.faceSize);
    programs.first.u().tile.set(baseTile);
    glActiveTexture(GL_TEXTURE0);  // u_faces
    glBindTexture(GL_TEXTURE_2D_ARRAY, faceDepths_[0].id());
    glActiveTexture(GL_TEXTURE1);  // u_backs
    glBindTexture(GL_TEXTURE_2D_ARRAY, two ? backs_.id() : 0);
    glActiveTexture(GL_TEXTURE2);  // u_faces2
    glBindTexture(GL_TEXTURE_2D_ARRAY, two ? faceDepths_[1].id() : 0);
    drawFaces(baseTile);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    // Levels 1..top, each from the one below, which is the only level the draw may read: the
    // one written is outside the sampled range, so this is no feedback loop (WebGL checks).
    glUseProgram(programs.reduce.id());
    glBindTexture(GL_TEXTURE_2D, pyramid);
    for (int mip = 1; mip <= topLevel_; ++mip) {
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, mip - 1);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, mip - 1);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, pyramid, mip);
      drawFaces(baseTile >> mip);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, topLevel_);
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  if (format_.mipmaps) {
    for (int layer = 0; layer < format_.layers; ++layer) {
      glBindTexture(GL_TEXTURE_CUBE_MAP, colour_[static_cast<size_t>(layer)].id());
      glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    }
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  }
}

void CubeCaptureTarget::buildBoxChain() const {
  if (!format_.boxChain || format_.mipmaps) return;
  glBindTexture(GL_TEXTURE_CUBE_MAP, colour_[0].id());
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
}

}  // namespace reflect
