// A colour + depth framebuffer the size of a frame, for rendering without a window (the CLI and
// the GL tests); readPixels returns what was drawn, top row first.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "core/image.h"
#include "core/result.h"
#include "gfx/gl_handle.h"

namespace reflect {

// The RGBA8 pixels of `framebuffer` (0: the canvas), width x height from the origin, top row
// first. Leaves framebuffer 0 bound.
RgbaImage readFramebuffer(GLuint framebuffer, int width, int height);

class OffscreenTarget {
 public:
  // floatColour: RGBA32F (needs EXT_color_buffer_float), read with readFloats.
  // depthBits: 16 or 24.
  static Result<OffscreenTarget> create(int width, int height, bool floatColour = false,
                                        int depthBits = 24);

  GLuint framebuffer() const { return framebuffer_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }
  RgbaImage readPixels() const;
  // RGB of every pixel of a float target, top row first.
  std::vector<glm::vec3> readFloats() const;
  // RGBA of every pixel of a float target, top row first (alpha may be past 1).
  std::vector<glm::vec4> readFloatsRgba() const;

 private:
  RenderbufferHandle colour_;
  RenderbufferHandle depth_;
  FramebufferHandle framebuffer_;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace reflect
