// Step through a frame, the demo's part: the last frame's step list, and a capture that tells the
// step callback of each step as the renderer draws it.
#include "app/demo.h"

namespace reflect {

std::vector<FrameStep> Demo::lastSteps() const {
  const AccuracySettings& accuracy =
      graphics_.renderer() ? graphics_.renderer()->accuracy() : accuracy_;
  if (stats_.width < 1 || stats_.height < 1) return frameSteps(lastPlan_, accuracy, {});
  return frameSteps(lastPlan_, accuracy,
                    viewDraws(plannedObjects(stats_.timeSeconds), stats_.width, stats_.height));
}

Result<PassCounts> Demo::captureInSteps(const FramePlan& plan) {
  SceneRenderer& renderer = *graphics_.renderer();
  const std::vector<FrameStep> steps =
      frameSteps(plan, renderer.accuracy(),
                 viewDraws(plannedObjects(stats_.timeSeconds), stats_.width, stats_.height));
  const int count = static_cast<int>(steps.size());
  const CaptureStepObserver observer = [&](int step) {
    // The renderer draws exactly the list's capture steps; a mismatch stops rather than lies.
    if (step + 1 >= count) return false;
    return stepCallback_(steps[static_cast<size_t>(step)], step, count);
  };
  return renderer.capture(scene_, stats_.timeSeconds, plan, camera_.eye(), &observer);
}

}  // namespace reflect
