// The faces view's read-back: the six faces of a probe's cube map as images, for one channel
// (core/cube_cross.h turns them into the unfolded cross). Faces come back top row first, the way
// cube-map faces are addressed (core/skybox_faces.h), so face texel (i, j) is image pixel (i, j).
#pragma once

#include "core/cube_cross.h"
#include "core/result.h"
#include "gfx/cube_capture_target.h"

namespace reflect {

// Colour and SecondLayer read the colour cube of layer 0 or 1 (an RGBA16F cube is read as floats
// and rounded to bytes). Distance reads the first layer's stored near codes as grey, near bright
// (255 at the capture's near plane, 0 at infinity: 255 (1 - code / 65535), which is 255 near / z).
// Irradiance reads the colour cube and gives its irradiance cube (core/irradiance.h): what a
// probe-lit reader of this probe takes, E / pi along each texel's direction. A channel the probe
// does not store (distances without the depth search, a second layer without
// layers) is an error that says what setting it needs. The framebuffer bindings are left as they
// were.
Result<CubeFaces> readCubeFaces(const CubeCaptureTarget& target, FacesChannel channel);

// Face `face` of the backs a two-layer capture's pass 3 stored (where the nearest surfaces end), as
// grey like the distance channel; where no back was stored (code 0), black. An error without a
// second layer.
Result<RgbaImage> readBacksFace(const CubeCaptureTarget& target, int face);

}  // namespace reflect
