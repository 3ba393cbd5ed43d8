// Step through a frame (Inside the frame): the image of one capture step, just after the renderer
// drew it. A pass into a face shows that face as the pass left it (its colour layer, the second
// layer, or the backs as grey), the depth pyramid step the probe's stored distances as a cross;
// the step's label is the title. The main step needs no image of its own: it is the frame.
// `reflect render --steps` and the page both make their images here, so they show the same.
#pragma once

#include <string>

#include "core/frame_steps.h"
#include "core/image.h"
#include "core/result.h"
#include "gfx/scene_renderer.h"

namespace reflect {

// A width x height image with the faces view's background: "STEP n OF m: label" at the top, then
// what step `index` of `count` drew, read back from its probe now (centred, shrunk by a whole
// factor when it does not fit). Call it right after the step (CaptureStepObserver); a main-pass
// step is an error.
Result<RgbaImage> captureStepImage(const SceneRenderer& renderer, const FrameStep& step, int index,
                                   int count, int width, int height);

// "step 3 of 20: ": what the images' titles and the CLI's lines start with.
std::string stepTitle(const FrameStep& step, int index, int count);

}  // namespace reflect
