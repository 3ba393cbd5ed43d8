// The static cube map of a scene's skybox and the pass that draws it behind everything.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "core/skybox_faces.h"
#include "gfx/capture_state.h"
#include "gfx/gl_handle.h"
#include "gfx/shader_program.h"

namespace reflect {

class SkyboxPass {
 public:
  // Uploads the faces (CLAMP_TO_EDGE, linear) and builds the program and the cube.
  static Result<SkyboxPass> create(const CubeFaces& faces);

  // Draws the sky where nothing else is (depth LEQUAL at the far plane); in a capture it is
  // stored infinitely far. `view` may contain a translation: only its rotation is used.
  void draw(const glm::mat4& projection, const glm::mat4& view, const CaptureState& pass) const;
  GLuint texture() const { return texture_.id(); }
  int faceSize() const { return faceSize_; }  // its faces' width (and height)
  // Active uniforms of its two programs that their tables do not set (for tests).
  std::vector<std::string> unlisted() const;

 private:
  // Two variants (capture_output.glsl): the main pass writes the colour alone, a capture its
  // distance and depth codes as well.
  struct Uniforms : UniformTable {
    Uniform<glm::mat4> viewRotationProjection{*this, "u_viewRotationProjection"};
    Uniform<int> skybox{*this, "u_skybox"};
    CaptureUniforms capture{*this};
  };
  using Program = TabledProgram<Uniforms>;
  static Result<Program> build(bool capture);
  Program main_, capture_;
  TextureHandle texture_;
  VertexArrayHandle vao_;
  BufferHandle vertices_;
  int faceSize_ = 0;
};

}  // namespace reflect
