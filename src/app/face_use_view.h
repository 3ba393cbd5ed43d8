// The face-use view (Inside the frame): the frame with each mirror and glass pixel painted in the
// colour of the cube face its lookup read (core/face_use.h), and a legend of how many pixels each
// face serves beside what the frame did to it (captured, stale, empty). The page shows it on the
// canvas in place of the picture; natively `reflect render --face-use FILE` writes it. One
// function for both, so they show the same pixels.
#pragma once

#include <functional>

#include "core/face_ages.h"
#include "core/frame_planner.h"
#include "core/image.h"
#include "core/result.h"
#include "core/scene.h"

namespace reflect {

// `frame` is the finished frame; `drawLookups` renders the same frame's lookup directions into the
// float framebuffer it is given (of the frame's size). The legend's marks are those of
// `plan`'s `probe`th probe (faces_view.h shownProbe; the title names its object); the painted
// pixels are every reflector's.
// Fails with a message when the GL cannot render into a float target (no EXT_color_buffer_float).
Result<RgbaImage> composeFaceUseView(
    const Scene& scene, const FramePlan& plan, const FaceAges& ages,
    const std::function<void(unsigned framebuffer, int width, int height)>& drawLookups,
    RgbaImage frame, int probe = 1);

}  // namespace reflect
