// Step through a frame (Inside the frame): the ordered list of draws a frame's passes make, from
// its FramePlan. For each captured probe, for each face it redraws, each capture pass (the colour
// of the nearest surfaces; with two layers also the backs and the second layer), then the probe's
// depth pyramid when it stores depths; last, the main pass. The renderer draws its passes by the
// same rules (capturePasses, capturesDepths), so the list and the frame cannot disagree; the page
// and `reflect render --steps` show these labels and counts.
#pragma once

#include <string>
#include <vector>

#include "core/accuracy_settings.h"
#include "core/frame_planner.h"

namespace reflect {

// The passes of capture_output.glsl, as the renderer numbers them (CaptureState::layer).
enum class StepPass {
  Colour = 1,       // pass 1: the nearest surfaces, into layer 1 (colour and depths)
  SecondLayer = 2,  // pass 2: what the nearest surfaces hide, into layer 2
  Backs = 3,        // pass 3: where the nearest surfaces end (the backs, depths only)
  DepthPyramid,     // the hierarchical search's min/max pyramid of the faces drawn
  Main,             // the main camera's pass, to the screen
};

struct FrameStep {
  StepPass pass = StepPass::Main;
  int probe = -1;      // index in FramePlan::probes (-1: the main pass)
  int reflector = -1;  // the object that owns the probe
  int face = -1;       // 0..5 in GL order (capture passes; -1 otherwise)
  size_t triangles = 0;
  int objects = 0;  // draws (objects) the step makes
  std::string label;
};

// The passes drawn into `face`, in the order the renderer draws them: pass 1 alone, or with two
// layers 1, then 3 (the backs pass 2 peels behind), then 2.
std::vector<StepPass> capturePasses(const FacePlan& face);
// Whether `probe`'s capture stores depths (and so builds a pyramid): the hierarchical search,
// unless the plain lookup suffices for every reflector of the probe.
bool capturesDepths(const ProbePlan& probe, const AccuracySettings& accuracy);

// The frame's steps in draw order. `mainDraws`: the main pass's draws (planViewDraws).
std::vector<FrameStep> frameSteps(const FramePlan& plan, const AccuracySettings& accuracy,
                                  const std::vector<DrawItem>& mainDraws);

// "colour", "second layer", "backs", "depth pyramid", "main pass".
const char* stepPassName(StepPass pass);

}  // namespace reflect
