#include "gfx/depth_pyramid_programs.h"

namespace reflect {

Result<std::unique_ptr<DepthPyramidPrograms>> DepthPyramidPrograms::create() {
  using Built = Result<std::unique_ptr<DepthPyramidPrograms>>;
  Result<ShaderProgram> first = ShaderProgram::build("fullscreen.vert", "depth_pyramid.frag");
  if (!first) return Built::failure(first.error());
  Result<ShaderProgram> reduce = ShaderProgram::build("fullscreen.vert", "depth_reduce.frag");
  if (!reduce) return Built::failure(reduce.error());
  auto programs = std::make_unique<DepthPyramidPrograms>();
  programs->first = first.take();
  programs->reduce = reduce.take();
  const FirstUniforms& f = programs->firstUniforms;
  programs->firstUniforms.locate(programs->first);
  glUseProgram(programs->first.id());
  f.faces.set(0);
  f.backs.set(1);
  f.faces2.set(2);
  programs->reduceUniforms.locate(programs->reduce);
  glUseProgram(programs->reduce.id());
  programs->reduceUniforms.source.set(0);
  glUseProgram(0);
  return programs;
}

}  // namespace reflect
