// Step through a frame, the demo's part: the last frame's step list, and a capture that tells the
// step callback of each step as the renderer draws it.
#include "app/demo.h"

#include <algorithm>

#include "app/frame_step_view.h"

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

Result<std::vector<FrameStep>> Demo::drawFrameStep(int step, unsigned framebuffer, int width,
                                                   int height) {
  using Out = Result<std::vector<FrameStep>>;
  SceneRenderer* renderer = graphics_.renderer();
  if (!renderer || width < 1 || height < 1) return Out::failure("nothing to draw yet");
  const double seconds = clock_.seconds();
  const std::vector<PlannedObject> objects = plannedObjects(seconds);
  FramePlanner fresh;  // the planner's memory would leave an unchanged frame nothing to capture
  fresh.setCosts(planner_.costs());
  const FramePlan plan =
      fresh.plan(objects, captureContext(), plannerSettings_, plannerView(width, height));
  const std::vector<DrawItem> draws = viewDraws(objects, width, height);
  std::vector<FrameStep> steps = frameSteps(plan, renderer->accuracy(), draws);
  const int count = static_cast<int>(steps.size());
  const int shown = std::clamp(step, 0, count - 1);
  ExactTracer* tracer = graphics_.tracer();
  if (tracer && !plan.traced.empty()) tracer->prepare(scene_, seconds, plan, camera_.eye());
  if (shown + 1 == count) {  // the main step: the whole frame
    Result<PassCounts> capture = renderer->capture(scene_, seconds, plan, camera_.eye());
    if (!capture) return Out::failure(capture.error());
    renderer->drawMain(scene_, seconds, plan, viewParams(width, height), draws, framebuffer, width,
                       height);
    return steps;
  }
  Result<RgbaImage> image = RgbaImage{};
  const CaptureStepObserver stopAtShown = [&](int index) {
    if (index != shown) return true;
    image =
        captureStepImage(*renderer, steps[static_cast<size_t>(index)], index, count, width, height);
    return false;
  };
  Result<PassCounts> capture =
      renderer->capture(scene_, seconds, plan, camera_.eye(), &stopAtShown);
  if (!capture) return Out::failure(capture.error());
  if (!image) return Out::failure(image.error());
  const std::string error = inside_.drawImage(image.value(), framebuffer, width, height);
  if (!error.empty()) return Out::failure(error);
  return steps;
}

}  // namespace reflect
