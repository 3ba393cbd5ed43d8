// The live environment: a cube texture whose faces are rendered one at a time through a
// framebuffer, with one depth renderbuffer shared by the six faces (they are drawn in turn).
// RGBA8 by default; RGBA16F where the capture also stores distances (alpha) or more precision.
#pragma once

#include <string>

#include "core/result.h"
#include "gfx/gl_handle.h"

namespace reflect {

struct CaptureFormat {
  int faceSize = 256;
  bool halfFloat = false;
  int depthBits = 24;
  bool mipmaps = false;
  bool operator==(const CaptureFormat& o) const {
    return faceSize == o.faceSize && halfFloat == o.halfFloat && depthBits == o.depthBits &&
           mipmaps == o.mipmaps;
  }
};

class CubeCaptureTarget {
 public:
  // faceSize is clamped to [1, GL_MAX_CUBE_MAP_TEXTURE_SIZE]; the framebuffer is checked complete
  // (an RGBA16F face needs EXT_color_buffer_half_float or _float: the error says so).
  static Result<CubeCaptureTarget> create(const CaptureFormat& format);

  // Binds the framebuffer with `face` (0..5, GL order) as colour and sets the viewport.
  void bindFace(int face) const;
  // After the faces are drawn: rebuilds the mip chain when the format asks for one.
  void finish() const;
  GLuint texture() const { return texture_.id(); }
  int faceSize() const { return format_.faceSize; }
  const CaptureFormat& format() const { return format_; }
  void abandon();

 private:
  TextureHandle texture_;
  RenderbufferHandle depth_;
  FramebufferHandle framebuffer_;
  CaptureFormat format_;
};

}  // namespace reflect
