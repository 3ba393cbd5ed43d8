// Step through a frame, the demo's part: the last frame's step list, and a capture that tells the
// step callback of each step as the renderer draws it. Both read the frame record.
#include "app/demo.h"

#include <algorithm>

#include "app/frame_step_view.h"

namespace reflect {

std::vector<FrameStep> Demo::lastSteps() const {
  const AccuracySettings& accuracy =
      graphics_.renderer() ? graphics_.renderer()->accuracy() : accuracy_;
  return frameSteps(lastFrame_.plan, accuracy, lastFrame_.mainDraws);
}

Result<PassCounts> Demo::captureInSteps(const FrameRecord& f) {
  SceneRenderer& renderer = *graphics_.renderer();
  const std::vector<FrameStep> steps = frameSteps(f.plan, renderer.accuracy(), f.mainDraws);
  const int count = static_cast<int>(steps.size());
  const CaptureStepObserver observer = [&](int step) {
    // The renderer draws exactly the list's capture steps; a mismatch stops rather than lies.
    if (step + 1 >= count) return false;
    return stepCallback_(steps[static_cast<size_t>(step)], step, count);
  };
  return renderer.capture(scene_, f.plan, f.view.eye, &observer);
}

Result<std::vector<FrameStep>> Demo::drawFrameStep(int step, unsigned framebuffer, int width,
                                                   int height) {
  using Out = Result<std::vector<FrameStep>>;
  SceneRenderer* renderer = graphics_.renderer();
  if (!renderer || width < 1 || height < 1) return Out::failure("nothing to draw yet");
  // The frame now as a first frame plans it: the planner's memory would leave an unchanged frame
  // nothing to capture. The demo's own planner, plan and stats are left as they were.
  const FrameRecord f = record(width, height, Planning::FirstFrame);
  std::vector<FrameStep> steps = frameSteps(f.plan, renderer->accuracy(), f.mainDraws);
  const int count = static_cast<int>(steps.size());
  const int shown = std::clamp(step, 0, count - 1);
  ExactTracer* tracer = graphics_.tracer();
  if (tracer && !f.plan.traced.empty()) tracer->prepare(scene_, f.plan, f.view.eye);
  if (shown + 1 == count) {  // the main step: the whole frame
    Result<PassCounts> capture = renderer->capture(scene_, f.plan, f.view.eye);
    if (!capture) return Out::failure(capture.error());
    renderer->drawMain(scene_, f.plan, f.view, f.mainDraws, framebuffer, width, height);
    return steps;
  }
  Result<RgbaImage> image = RgbaImage{};
  const CaptureStepObserver stopAtShown = [&](int index) {
    if (index != shown) return true;
    image =
        captureStepImage(*renderer, steps[static_cast<size_t>(index)], index, count, width, height);
    return false;
  };
  Result<PassCounts> capture = renderer->capture(scene_, f.plan, f.view.eye, &stopAtShown);
  if (!capture) return Out::failure(capture.error());
  if (!image) return Out::failure(image.error());
  const std::string error = inside_.drawImage(image.value(), framebuffer, width, height);
  if (!error.empty()) return Out::failure(error);
  return steps;
}

}  // namespace reflect
