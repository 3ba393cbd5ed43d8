#include "gfx/offscreen_target.h"

#include <algorithm>
#include <string>

namespace reflect {

Result<OffscreenTarget> OffscreenTarget::create(int width, int height, bool floatColour,
                                                int depthBits) {
  // The frame must fit a renderbuffer and a viewport, or it would be cropped without a word.
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
  GLint maxViewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
  maxSize = std::min({maxSize, maxViewport[0], maxViewport[1]});
  if (width < 1 || height < 1 || width > maxSize || height > maxSize) {
    return Result<OffscreenTarget>::failure("frame size " + std::to_string(width) + "x" +
                                            std::to_string(height) + " is outside 1.." +
                                            std::to_string(maxSize));
  }
  OffscreenTarget t;
  t.width_ = width;
  t.height_ = height;
  t.colour_ = RenderbufferHandle(genRenderbuffer());
  glBindRenderbuffer(GL_RENDERBUFFER, t.colour_.id());
  glRenderbufferStorage(GL_RENDERBUFFER, floatColour ? GL_RGBA32F : GL_RGBA8, width, height);
  t.depth_ = RenderbufferHandle(genRenderbuffer());
  glBindRenderbuffer(GL_RENDERBUFFER, t.depth_.id());
  glRenderbufferStorage(GL_RENDERBUFFER,
                        depthBits <= 16 ? GL_DEPTH_COMPONENT16 : GL_DEPTH_COMPONENT24, width,
                        height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  t.framebuffer_ = FramebufferHandle(genFramebuffer());
  glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t.colour_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth_.id());
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    return Result<OffscreenTarget>::failure("offscreen framebuffer incomplete");
  }
  return t;
}

RgbaImage readFramebuffer(GLuint framebuffer, int width, int height) {
  RgbaImage image;
  image.width = width;
  image.height = height;
  image.pixels.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  flipRows(image);
  return image;
}

RgbaImage OffscreenTarget::readPixels() const {
  return readFramebuffer(framebuffer_.id(), width_, height_);
}

std::vector<glm::vec4> OffscreenTarget::readFloatsRgba() const {
  std::vector<glm::vec4> rows(static_cast<size_t>(width_) * static_cast<size_t>(height_));
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, rows.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  // GL's rows come bottom-up.
  std::vector<glm::vec4> out(rows.size());
  const size_t w = static_cast<size_t>(width_);
  for (size_t y = 0; y < static_cast<size_t>(height_); ++y) {
    std::copy_n(&rows[(static_cast<size_t>(height_) - 1 - y) * w], w, &out[y * w]);
  }
  return out;
}

std::vector<glm::vec3> OffscreenTarget::readFloats() const {
  const std::vector<glm::vec4> rgba = readFloatsRgba();
  std::vector<glm::vec3> out;
  out.reserve(rgba.size());
  for (const glm::vec4& p : rgba) out.emplace_back(p);
  return out;
}

}  // namespace reflect
