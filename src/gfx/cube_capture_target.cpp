#include "gfx/cube_capture_target.h"

#include <algorithm>

namespace reflect {

Result<CubeCaptureTarget> CubeCaptureTarget::create(const CaptureFormat& format) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &maxSize);
  CubeCaptureTarget t;
  t.format_ = format;
  t.format_.faceSize = std::clamp(format.faceSize, 1, std::max(1, static_cast<int>(maxSize)));
  const int size = t.format_.faceSize;

  t.texture_ = TextureHandle(genTexture());
  glBindTexture(GL_TEXTURE_CUBE_MAP, t.texture_.id());
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

  t.depth_ = RenderbufferHandle(genRenderbuffer());
  glBindRenderbuffer(GL_RENDERBUFFER, t.depth_.id());
  glRenderbufferStorage(GL_RENDERBUFFER,
                        format.depthBits <= 16 ? GL_DEPTH_COMPONENT16 : GL_DEPTH_COMPONENT24, size,
                        size);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);

  t.framebuffer_ = FramebufferHandle(genFramebuffer());
  glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X,
                         t.texture_.id(), 0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
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

void CubeCaptureTarget::bindFace(int face) const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                         GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(face), texture_.id(),
                         0);
  glViewport(0, 0, format_.faceSize, format_.faceSize);
}

void CubeCaptureTarget::finish() const {
  if (!format_.mipmaps) return;
  glBindTexture(GL_TEXTURE_CUBE_MAP, texture_.id());
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
}

void CubeCaptureTarget::abandon() {
  texture_.abandon();
  depth_.abandon();
  framebuffer_.abandon();
}

}  // namespace reflect
