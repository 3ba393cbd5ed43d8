#include "gfx/error_view.h"

#include <vector>

namespace reflect {

Result<ErrorView> ErrorView::create() {
  return withBuiltProgram<decltype(program_)>("fullscreen.vert", "error_view.frag",
                                              [](auto program) {
                                                ErrorView v;
                                                v.program_ = std::move(program);
                                                v.vao_ = VertexArrayHandle(genVertexArray());
                                                return v;
                                              });
}

std::string ErrorView::resize(int width, int height) {
  if (width == width_ && height == height_) return {};
  width_ = width;
  height_ = height;
  for (int i = 0; i < 3; ++i) {
    Target& t = targets_[i];
    t.colour = TextureHandle(genTexture());
    glBindTexture(GL_TEXTURE_2D, t.colour.id());
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, width, height);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    t.framebuffer = FramebufferHandle(genFramebuffer());
    glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t.colour.id(), 0);
    if (i < 2) {
      t.depth = RenderbufferHandle(genRenderbuffer());
      glBindRenderbuffer(GL_RENDERBUFFER, t.depth.id());
      glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth.id());
    }
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      width_ = height_ = 0;
      return "the error view's targets are incomplete";
    }
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return checkGlError("error view targets") ? std::string() : "GL error sizing the error view";
}

ErrorViewStats ErrorView::compose(GLuint framebuffer) {
  glDisable(GL_DEPTH_TEST);
  glUseProgram(program_.id());
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, targets_[0].colour.id());
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, targets_[1].colour.id());
  const Uniforms& u = program_.u();
  u.current.set(0);
  u.exact.set(1);
  glBindVertexArray(vao_.id());
  glViewport(0, 0, width_, height_);
  // The differences first, read back; then the picture.
  glBindFramebuffer(GL_FRAMEBUFFER, targets_[2].framebuffer.id());
  u.output.set(1);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<uint8_t> pixels(static_cast<size_t>(width_) * static_cast<size_t>(height_) * 4);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  u.output.set(0);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glUseProgram(0);
  glEnable(GL_DEPTH_TEST);
  checkGlError("error view");
  return summariseErrorImage(pixels);
}

}  // namespace reflect
