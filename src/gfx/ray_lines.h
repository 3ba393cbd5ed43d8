// Pick a pixel's rays drawn as 3D lines over the finished frame (app/pick_overlay.h): world-space
// segments, each in its own colour, drawn by the main camera with the depth test off, so a ray
// behind the mirror still shows. GL_LINES at one pixel wide (WebGL2 draws no wider lines).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "gfx/gl_handle.h"
#include "gfx/shader_program.h"
#include "gfx/uniform_table.h"

namespace reflect {

struct RaySegment {
  glm::vec3 from{0.0f};
  glm::vec3 to{0.0f};
  glm::vec3 colour{1.0f};
};

class RayLines {
 public:
  static Result<RayLines> create();
  // Uploads `segments` (kept until the next call) for draw().
  void set(const std::vector<RaySegment>& segments);
  // Draws them into the bound framebuffer's `width` x `height`.
  void draw(const glm::mat4& viewProjection, int width, int height) const;

 private:
  struct Uniforms : UniformTable {
    Uniform<glm::mat4> viewProjection{*this, "u_viewProjection"};
  };
  TabledProgram<Uniforms> program_;
  BufferHandle buffer_;
  VertexArrayHandle vertexArray_;
  GLsizei vertices_ = 0;
};

}  // namespace reflect
