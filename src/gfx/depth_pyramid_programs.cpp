#include "gfx/depth_pyramid_programs.h"

namespace reflect {

Result<DepthPyramidPrograms> DepthPyramidPrograms::create() {
  using Built = Result<DepthPyramidPrograms>;
  auto first = TabledProgram<FirstUniforms>::build("fullscreen.vert", "depth_pyramid.frag");
  if (!first) return Built::failure(first.error());
  auto reduce = TabledProgram<ReduceUniforms>::build("fullscreen.vert", "depth_reduce.frag");
  if (!reduce) return Built::failure(reduce.error());
  DepthPyramidPrograms programs;
  programs.first = first.take();
  programs.reduce = reduce.take();
  glUseProgram(programs.first.id());
  programs.first.u().faces.set(0);
  programs.first.u().backs.set(1);
  programs.first.u().faces2.set(2);
  glUseProgram(programs.reduce.id());
  programs.reduce.u().source.set(0);
  glUseProgram(0);
  return programs;
}

std::vector<std::string> DepthPyramidPrograms::unlisted() const {
  std::vector<std::string> out = first.unlisted();
  for (const std::string& name : reduce.unlisted()) out.push_back(name);
  return out;
}

}  // namespace reflect
