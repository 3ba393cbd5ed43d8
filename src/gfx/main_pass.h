// The main pass: the frame's own view, every object as the plan draws it (planViewDraws), then
// the skybox behind them, into the given framebuffer. Mirrors and glass read what the capture
// left (or trace), through the pass drawer's environment binding.
#pragma once

#include <vector>

#include "gfx/pass_drawer.h"
#include "gfx/skybox_pass.h"

namespace reflect {

struct ViewParams {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::vec3 eye{0.0f};
};

// Where the main pass draws: a framebuffer (0: the default one) of width x height, and what
// mirrors and glass write there (environment.frag's u_outputDirection: 0 their colour).
struct MainTarget {
  unsigned framebuffer = 0;
  int width = 0, height = 0;
  int outputDirections = 0;
};

PassCounts drawMainPass(const PassDrawer& drawer, const SkyboxPass* sky, const Scene& scene,
                        const FramePlan& plan, const ViewParams& camera,
                        const std::vector<DrawItem>& draws, const MainTarget& target);

}  // namespace reflect
