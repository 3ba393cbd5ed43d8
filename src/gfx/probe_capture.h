// The capture: each probe's planned cube faces, pass by pass (core/frame_steps.h names the passes
// and their order, one rule for the renderer and the step list): objects at their planned level
// of detail, a second, peeled layer where the plan asks for one, then the faces' depth pyramid.
// It owns the probes' cube targets, made (or remade) for the format each probe needs. With an
// observer it is told after each step and may stop the capture there (Inside the frame, "Step
// through a frame"). The rough levels are filtered after it (prefiltered_probes.h).
#pragma once

#include <functional>
#include <map>
#include <vector>

#include <glm/glm.hpp>

#include "core/accuracy_settings.h"
#include "core/frame_planner.h"
#include "core/frame_steps.h"
#include "core/result.h"
#include "core/scene.h"
#include "gfx/cube_capture_target.h"
#include "gfx/depth_pyramid_programs.h"
#include "gfx/gl_handle.h"
#include "gfx/pass_drawer.h"
#include "gfx/skybox_pass.h"

namespace reflect {

// Step through a frame: told after each capture step (core/frame_steps.h's order, from 0) is
// drawn; returns false to stop the capture there.
using CaptureStepObserver = std::function<bool(int step)>;

// One frame's capture.
struct CaptureRequest {
  const Scene& scene;
  const FramePlan& plan;
  glm::vec3 lightingEye;  // the main camera's eye: the course lights captures as seen from it
  const AccuracySettings& accuracy;
  const SkyboxPass* sky;                 // null: no skybox
  const CaptureStepObserver* afterStep;  // null: no stepping
};

class ProbeCapture {
 public:
  static Result<ProbeCapture> create();
  struct Outcome {
    PassCounts counts;
    bool finished = true;  // false: the step observer stopped it
  };
  Result<Outcome> capture(const CaptureRequest& request, const PassDrawer& drawer);
  // After the captures: the box chain of each probe that has one and was redrawn this frame (the
  // renderer times it with the filters: it is what the lobe taps read).
  void buildBoxChains(const FramePlan& plan) const;
  // The cube captured for the probe owned by object `owner` (null before its first capture).
  const CubeCaptureTarget* target(int owner) const;
  // Bound to the pyramid unit where a reflector has no depth chain (environment_binding.h).
  GLuint emptyPyramid() const { return emptyPyramid_.id(); }
  // Bound to kLobeUnit with a lobe-tap reader's cube: reads its box chain trilinearly, whatever
  // the cube's own filter (bound at each draw: another renderer's sampler, deleted, would leave
  // the unit without one).
  GLuint lobeSampler() const { return lobeSampler_.id(); }
  // The depth pyramid programs' uniforms that nothing sets, for tests.
  std::vector<std::string> unlisted() const { return pyramid_.unlisted(); }

 private:
  ProbeCapture() = default;
  struct Job;  // what every face of one capture shares
  Result<CubeCaptureTarget*> targetFor(const Scene& scene, const ProbePlan& probe,
                                       const AccuracySettings& accuracy);
  // Draws `face`'s passes; false when the step observer stopped the capture.
  bool captureFace(Job& job, const ProbePlan& probe, const CubeCaptureTarget& t,
                   const FacePlan& face, PassCounts& counts);
  PassCounts capturePass(const Job& job, const ProbePlan& probe, const CubeCaptureTarget& t,
                         const FacePlan& face, StepPass pass,
                         const std::vector<DrawItem>& backDraws);

  std::map<int, CubeCaptureTarget> targets_;  // by owning object's index
  DepthPyramidPrograms pyramid_;
  // Bound to the depth units whenever nothing else is, so no program ever samples a texture the
  // pass renders into (a feedback loop WebGL refuses to draw).
  TextureHandle emptyDepths_;
  TextureHandle emptyPyramid_;
  SamplerHandle lobeSampler_;           // kLobeUnit's: the lobe taps read the box chain trilinearly
  VertexArrayHandle emptyVertexArray_;  // the reduction's fullscreen triangle has no attributes
};

}  // namespace reflect
