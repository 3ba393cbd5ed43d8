// Draws an RGBA image made on the CPU onto a framebuffer, pixel for pixel and centred (cut where
// it is larger): how the page shows the faces view, which core composes (core/cube_cross.h).
#pragma once

#include <array>

#include "core/image.h"
#include "core/result.h"
#include "gfx/gl_handle.h"
#include "gfx/shader_program.h"
#include "gfx/uniform_table.h"

namespace reflect {

class ImageBlit {
 public:
  static Result<ImageBlit> create();
  // Uploads `image` (top row first) and fills the bound framebuffer's `width` x `height` with it,
  // `background` (RGBA8) around it.
  void draw(const RgbaImage& image, int width, int height,
            const std::array<uint8_t, 4>& background);

 private:
  struct Uniforms : UniformTable {
    Uniform<int> image{*this, "u_image"};  // unit 0
    Uniform<glm::ivec2> origin{*this, "u_origin"};
    Uniform<glm::vec3> background{*this, "u_background"};
  };
  TabledProgram<Uniforms> program_;
  TextureHandle texture_;
  int textureWidth_ = 0, textureHeight_ = 0;  // the size texture_ was made for
  VertexArrayHandle vertexArray_;             // empty: the full-screen triangle needs no attributes
};

}  // namespace reflect
