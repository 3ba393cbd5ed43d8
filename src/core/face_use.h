// The face-use view (Inside the frame): each mirror and glass pixel painted with the colour of the
// cube face its lookup read, so a class sees which faces a reflector really uses, and that the
// faces the planner skipped are read nowhere. The face of a pixel is the face rule of GL's cube
// map selection (cubeFaceCoord, core/cube_sampling.h) applied to the direction the renderer's own
// shader looked up along (its lookup-direction output): no second rule for the view.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/cube_cross.h"
#include "core/image.h"

namespace reflect {

// What the renderer's lookup-direction pass leaves in a pixel's alpha (shaders/environment.frag,
// u_outputDirection 1): which lookup the rgb direction belongs to.
inline constexpr float kLookupMarkProbe = 2.0f;   // a cube map lookup (probe or skybox)
inline constexpr float kLookupMarkTraced = 3.0f;  // a traced ray: no face was read

// Six distinct colours, GL face order (+X red, -X cyan, +Y green, -Y magenta, +Z blue, -Z yellow:
// each axis's two faces are complements, so opposite faces never look alike).
inline constexpr std::array<std::array<uint8_t, 4>, 6> kFaceUseColours{{
    {230, 40, 40, 255},
    {40, 210, 230, 255},
    {50, 200, 60, 255},
    {220, 60, 220, 255},
    {50, 90, 240, 255},
    {240, 220, 40, 255},
}};
// Traced reflector pixels: a neutral grey (they read no face).
inline constexpr std::array<uint8_t, 4> kFaceUseTraced{150, 150, 150, 255};

// Pixels that read each face, and traced pixels, in one frame.
struct FaceUseCounts {
  std::array<size_t, 6> faces{};
  size_t traced = 0;
};

// The face (GL order) a lookup pixel read, -1 for a traced pixel, -2 for a pixel that is not a
// mirror or glass (any other alpha).
int faceOfLookup(const glm::vec4& lookup);

// Paints `frame` in place: lookup pixels in their face's colour, traced pixels grey, every other
// pixel dimmed to a third so the reflectors stand out. `lookups` is the lookup-direction pass of
// the same frame (same size, top row first). Returns the counts.
FaceUseCounts paintFaceUse(RgbaImage& frame, const std::vector<glm::vec4>& lookups);

// The legend's line for face `face`: "+X  1234 PX  CAPTURED" (or the faces view's "STALE 3
// FRAMES", "EMPTY": core/cube_cross.h faceStatus).
std::string faceUseLine(int face, size_t pixels, const FaceMark& mark);

// The whole view: `frame` painted (paintFaceUse) with the legend (a swatch and faceUseLine per
// face, and the traced count) over its bottom-left corner and `title` at its top.
RgbaImage composeFaceUse(RgbaImage frame, const std::vector<glm::vec4>& lookups,
                         const std::array<FaceMark, 6>& marks, const std::string& title);

}  // namespace reflect
