// The live error view (show error): the current mode's frame and the exact mode's, each rendered
// into a texture of the frame's size, compared on the GPU (shaders/error_view.frag): a heat map
// over the reflectors drawn into the output framebuffer, and the per-pixel differences read back
// and summed (core/error_view_stats.h).
#pragma once

#include "core/error_view_stats.h"
#include "core/result.h"
#include "gfx/gl_handle.h"
#include "gfx/shader_program.h"
#include "gfx/uniform_table.h"

namespace reflect {

class ErrorView {
 public:
  static Result<ErrorView> create();

  // Sizes the targets (a no-op when they have the size). Returns "" or a message.
  std::string resize(int width, int height);
  // Where the frame in the current mode, and the exact mode's (its reflectors at alpha 0), go.
  GLuint currentFramebuffer() const { return targets_[0].framebuffer.id(); }
  GLuint exactFramebuffer() const { return targets_[1].framebuffer.id(); }
  // The heat map into `framebuffer`, and the numbers.
  ErrorViewStats compose(GLuint framebuffer);

 private:
  struct Target {
    TextureHandle colour;
    RenderbufferHandle depth;
    FramebufferHandle framebuffer;
  };
  ErrorView() = default;

  struct Uniforms : UniformTable {
    Uniform<int> current{*this, "u_current"};  // unit 0
    Uniform<int> exact{*this, "u_exact"};      // unit 1
    Uniform<int> output{*this, "u_output"};    // 1: the differences, 0: the picture
  };
  TabledProgram<Uniforms> program_;
  VertexArrayHandle vao_;
  Target targets_[3];  // current, exact, differences
  int width_ = 0, height_ = 0;
};

}  // namespace reflect
