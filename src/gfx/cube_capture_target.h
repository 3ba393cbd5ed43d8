// The live environment: an RGBA8 cube texture whose faces are rendered one at a time through a
// framebuffer, with one depth renderbuffer shared by the six faces (they are drawn in turn).
#pragma once

#include <string>

#include "core/result.h"
#include "gfx/gl_handle.h"

namespace reflect {

class CubeCaptureTarget {
 public:
  // faceSize is clamped to [1, GL_MAX_CUBE_MAP_TEXTURE_SIZE]; the framebuffer is checked complete.
  static Result<CubeCaptureTarget> create(int faceSize);

  // Binds the framebuffer with `face` (0..5, GL order) as colour and sets the viewport.
  void bindFace(int face) const;
  GLuint texture() const { return texture_.id(); }
  int faceSize() const { return faceSize_; }
  void abandon();

 private:
  TextureHandle texture_;
  RenderbufferHandle depth_;
  FramebufferHandle framebuffer_;
  int faceSize_ = 0;
};

}  // namespace reflect
