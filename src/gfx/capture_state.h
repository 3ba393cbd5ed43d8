// What every fragment shader's writeOutputs (shaders/capture_output.glsl) needs to know of the pass
// it draws in, and the texture units the programs share.
#pragma once

#include <glm/glm.hpp>
#include "gfx/uniform_table.h"

namespace reflect {

// Texture units, fixed per sampler across programs (two samplers of different types may not
// share a unit in one program).
inline constexpr GLint kEnvironmentUnit = 0;   // samplerCube: a probe's (first layer) colours
inline constexpr GLint kPyramidUnit = 1;       // usampler2D: its depth pyramid (both layers)
inline constexpr GLint kEnvironment2Unit = 2;  // samplerCube: its second layer's colours
inline constexpr GLint kPeelDepthsUnit = 4;    // usampler2DArray: the layer a peel draws behind
inline constexpr GLint kPeelBacksUnit = 5;     // usampler2DArray: the backs it also peels behind
inline constexpr GLint kPrefilteredUnit = 10;  // samplerCube: a rough reader's prefiltered levels
// samplerCube: a rough reader's probe colours with their box chain, through ProbeCapture's
// trilinear sampler, whatever the cube's own filter.
inline constexpr GLint kLobeUnit = 13;
// samplerCube: a probe-lit object's probe, its box mip chain read trilinearly (the irradiance
// parallax's taps, parallax_feedback.vert).
inline constexpr GLint kParallaxUnit = 14;

struct CaptureState {
  int layer = 0;  // 0 the main pass, 1 a capture's first layer, 2 its second
  glm::vec3 centre{0.0f};
  glm::vec3 axis{0.0f, 0.0f, -1.0f};  // the face's look direction
  float unit = 1.0f;                  // the capture's near plane
  int face = 0;
};

// capture_output.glsl's uniforms, entries of their program's table (uniform_table.h). A shader
// that never captures may lose some to the optimiser: they are then -1, which GL ignores.
struct CaptureUniforms {
  UniformTable& table;
  Uniform<int> layer{table, "u_captureLayer"};
  Uniform<glm::vec3> centre{table, "u_captureCentre"};
  Uniform<glm::vec3> axis{table, "u_captureAxis"};
  Uniform<float> unit{table, "u_captureUnit"};
  Uniform<int> face{table, "u_captureFace"};
  Uniform<float> extent{table, "u_captureExtent"};  // set per draw: the drawn object's size
  Uniform<int> peelDepths{table, "u_peelDepths"};
  Uniform<int> peelBacks{table, "u_peelBacks"};

  // The peel's texture units, once, into the program in use (after the table is located).
  void setUnits() const {
    peelDepths.set(kPeelDepthsUnit);
    peelBacks.set(kPeelBacksUnit);
  }
  // The pass, into the program in use.
  void set(const CaptureState& s) const {
    layer.set(s.layer);
    centre.set(s.centre);
    axis.set(s.axis);
    unit.set(s.unit);
    face.set(s.face);
  }
};

}  // namespace reflect
