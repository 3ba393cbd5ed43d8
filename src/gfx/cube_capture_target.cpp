#include "gfx/cube_capture_target.h"

#include <algorithm>

namespace reflect {

Result<CubeCaptureTarget> CubeCaptureTarget::create(int faceSize) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &maxSize);
  CubeCaptureTarget t;
  t.faceSize_ = std::clamp(faceSize, 1, std::max(1, static_cast<int>(maxSize)));

  t.texture_ = TextureHandle(genTexture());
  glBindTexture(GL_TEXTURE_CUBE_MAP, t.texture_.id());
  for (GLenum face = 0; face < 6; ++face) {
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA8, t.faceSize_, t.faceSize_, 0,
                 GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);

  t.depth_ = RenderbufferHandle(genRenderbuffer());
  glBindRenderbuffer(GL_RENDERBUFFER, t.depth_.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, t.faceSize_, t.faceSize_);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);

  t.framebuffer_ = FramebufferHandle(genFramebuffer());
  glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X,
                         t.texture_.id(), 0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    return Result<CubeCaptureTarget>::failure("cube capture framebuffer incomplete (status 0x" +
                                              std::to_string(status) + ")");
  }
  if (!checkGlError("create cube capture target")) {
    return Result<CubeCaptureTarget>::failure("GL error while creating the cube capture target");
  }
  return t;
}

void CubeCaptureTarget::bindFace(int face) const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                         GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(face), texture_.id(),
                         0);
  glViewport(0, 0, faceSize_, faceSize_);
}

void CubeCaptureTarget::abandon() {
  texture_.abandon();
  depth_.abandon();
  framebuffer_.abandon();
}

}  // namespace reflect
