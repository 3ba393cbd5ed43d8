// Step through a frame, natively: `reflect render --steps DIR` renders its frame while writing one
// PNG per step, in the frame's own draw order, and a line per step for the terminal.
#pragma once

#include <string>
#include <vector>

#include "app/demo.h"
#include "core/image.h"
#include "core/result.h"

namespace reflect {

// Renders the frame at scene time `seconds`, as renderFrameAt does, writing DIR/step-01.png ...:
// each capture step's image (frame_step_view.h) just after the renderer drew it, then the main
// pass's, which is the frame itself, pixel for pixel. Appends "step 1 of 20: label" per step to
// `lines`. Returns the frame, or why not (DIR is not a writable folder, a PNG could not be
// written, the renderer's steps were not the list's).
Result<RgbaImage> renderFrameInSteps(Demo& demo, double seconds, int width, int height,
                                     const std::string& dir, std::vector<std::string>& lines);

// DIR/step-07.png: two digits at least, more when there are a hundred steps or more.
std::string stepFileName(const std::string& dir, int index, int count);

}  // namespace reflect
