// The faces view (Inside the frame): the cube map of the last frame's first probe, read back and
// unfolded as a labelled cross. The page shows the image on the canvas in place of the picture;
// natively `reflect render --faces FILE` writes it. One function for both, so they show the same
// pixels.
#pragma once

#include <string>

#include "core/face_ages.h"
#include "core/frame_planner.h"
#include "core/image.h"
#include "core/result.h"
#include "core/scene.h"
#include "gfx/scene_renderer.h"

namespace reflect {

// The probe a view shows: `plan`'s `probe`th (1 = the first; past the last, the last), or null
// when the frame has none.
const ProbePlan* shownProbe(const FramePlan& plan, int probe);

// The cross of `plan`'s `probe`th probe (shownProbe; the title names its object and which of how
// many probes it is), marked by `ages`. Fails with a message saying why when the frame captured no
// probe (every reflector traced) or the probe does not store `channel`. With `fitWidth` and
// `fitHeight` (the page's canvas) the faces shrink by a whole factor until the cross fits, and
// the title says so; 0 (natively): texel for pixel.
Result<RgbaImage> composeFacesView(const SceneRenderer& renderer, const Scene& scene,
                                   const FramePlan& plan, const FaceAges& ages,
                                   FacesChannel channel, int fitWidth = 0, int fitHeight = 0,
                                   int probe = 1);

// A message as an image (the view's background, the text in lines of at most `width` pixels):
// what the page shows in the view's place when there is nothing to show.
RgbaImage messageImage(const std::string& text, int width, int height);

}  // namespace reflect
