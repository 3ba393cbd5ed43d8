// What every fragment shader's writeOutputs (shaders/capture_output.glsl) needs to know of the pass
// it draws in, and the texture units the programs share.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gfx/shader_program.h"

namespace reflect {

// Texture units, fixed per sampler across programs (two samplers of different types may not
// share a unit in one program).
inline constexpr GLint kEnvironmentUnit = 0;   // samplerCube: a probe's (first layer) colours
inline constexpr GLint kPyramidUnit = 1;       // usampler2D: its depth pyramid (both layers)
inline constexpr GLint kEnvironment2Unit = 2;  // samplerCube: its second layer's colours
inline constexpr GLint kPeelDepthsUnit = 4;    // usampler2DArray: the layer a peel draws behind
inline constexpr GLint kPeelBacksUnit = 5;     // usampler2DArray: the backs it also peels behind
inline constexpr GLint kPrefilteredUnit = 10;  // samplerCube: a rough reader's prefiltered levels

struct CaptureState {
  int layer = 0;  // 0 the main pass, 1 a capture's first layer, 2 its second
  glm::vec3 centre{0.0f};
  glm::vec3 axis{0.0f, 0.0f, -1.0f};  // the face's look direction
  float unit = 1.0f;                  // the capture's near plane
  int face = 0;
  // The pass cannot see how deep what it draws is: the far ends take kThickness.
  bool guessDepth = false;
};

struct CaptureUniforms {
  GLint layer = -1, centre = -1, axis = -1, unit = -1, face = -1, extent = -1, guessDepth = -1;

  static CaptureUniforms of(const ShaderProgram& p) {
    // Optional: a shader that never captures may lose some to the optimiser.
    CaptureUniforms u{p.optionalUniform("u_captureLayer"), p.optionalUniform("u_captureCentre"),
                      p.optionalUniform("u_captureAxis"),  p.optionalUniform("u_captureUnit"),
                      p.optionalUniform("u_captureFace"),  p.optionalUniform("u_captureExtent")};
    glUseProgram(p.id());
    glUniform1i(p.optionalUniform("u_peelDepths"), kPeelDepthsUnit);
    glUniform1i(p.optionalUniform("u_peelBacks"), kPeelBacksUnit);
    return u;
  }

  // Sets them in the program in use.
  void set(const CaptureState& s) const {
    glUniform1i(layer, s.layer);
    glUniform3fv(centre, 1, glm::value_ptr(s.centre));
    glUniform3fv(axis, 1, glm::value_ptr(s.axis));
    glUniform1f(unit, s.unit);
    glUniform1i(face, s.face);
    glUniform1i(guessDepth, s.guessDepth ? 1 : 0);
  }
};

}  // namespace reflect
