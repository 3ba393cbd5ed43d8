// The two programs that build a probe's depth pyramid (fullscreen.vert with depth_pyramid.frag
// for level 0, depth_reduce.frag for each level above) and their uniforms as tables
// (uniform_table.h). The scene renderer builds them once; each capture target's finish() uses
// them.
#pragma once

#include <string>
#include <vector>

#include "core/result.h"
#include "gfx/shader_program.h"
#include "gfx/uniform_table.h"

namespace reflect {

struct DepthPyramidPrograms {
  struct FirstUniforms : UniformTable {
    Uniform<int> faces{*this, "u_faces"};    // unit 0
    Uniform<int> backs{*this, "u_backs"};    // unit 1
    Uniform<int> faces2{*this, "u_faces2"};  // unit 2
    Uniform<int> layers{*this, "u_layers"};
    Uniform<int> faceSize{*this, "u_faceSize"};
    Uniform<int> tile{*this, "u_tile"};
  };
  struct ReduceUniforms : UniformTable {
    Uniform<int> source{*this, "u_source"};  // unit 0
  };

  // Builds both and sets their samplers' units. Failure names the shader file.
  static Result<DepthPyramidPrograms> create();
  // The active uniforms their tables do not set (for tests).
  std::vector<std::string> unlisted() const;

  TabledProgram<FirstUniforms> first;
  TabledProgram<ReduceUniforms> reduce;
};

}  // namespace reflect
