// The faces view: the live cube map unfolded as a horizontal cross (the layout facesFromCross
// reads, kCrossCells), each face labelled with its name, its look and up vectors from the course's
// table (core/cube_faces.h) and whether this frame captured it. Stale faces (left from an earlier
// frame by a policy that skips faces) are dimmed to half and show their age in frames.
//
// The face squares hold the faces' own pixels, untouched (dimming aside): labels and marks sit in
// a margin around each square and in a legend strip below the cross, so a test can compare the view
// with a read-back of the cube map texel for texel.
#pragma once

#include <array>
#include <string>

#include "core/image.h"
#include "core/skybox_faces.h"

namespace reflect {

// The view's background (the page fills the canvas around the cross with it).
inline constexpr std::array<uint8_t, 4> kCrossBackground{24, 24, 28, 255};
// A width x height image of that background, for the views' other images (messages, steps).
RgbaImage backgroundImage(int width, int height);

// What the frame did to one face.
struct FaceMark {
  bool captured = false;     // drawn this frame
  int ageFrames = 0;         // frames since it was last drawn (0 when captured)
  bool everCaptured = true;  // false: the face was never drawn (an empty probe)
};

// What the faces view shows of each texel.
enum class FacesChannel {
  Colour,       // the colour layer
  Distance,     // the stored distance from the probe centre, grey, near bright
  SecondLayer,  // the second depth layer's colour (layered search)
  Irradiance,   // the colour layer's order-2 irradiance: what a probe-lit reader facing there takes
};

const char* facesChannelName(FacesChannel channel);

// Where face `face`'s square lies in the view, and the view's size, for squares of `faceSize`.
struct CrossGeometry {
  int faceSize = 0;
  int margin = 0;  // around each square, where the face's name and mark go
  int width = 0;
  int height = 0;
  std::array<std::array<int, 2>, 6> squareOrigin{};  // top-left pixel of each face's square
};
CrossGeometry crossGeometry(int faceSize);

// The smallest whole factor k (1, 2, 3, ...) by which faces of `faceSize` must shrink for the view
// to fit `width` x `height` (0: no limit); the view never shrinks below 8-texel faces.
int crossShrinkFactor(int faceSize, int width, int height);
// `faces` shrunk by `factor` (each texel the mean of a factor x factor block, rounded); 1 returns
// them as they are. The page's canvas is often smaller than a 256-texel cross; the labels stay
// readable because the faces shrink, not the whole image.
CubeFaces shrinkFaces(const CubeFaces& faces, int factor);

// "+X  LOOK (1,0,0)  UP (0,-1,0)": the course's table, one line a face.
std::string faceLabel(int face);
// "CAPTURED", "STALE 3 FRAMES" or "EMPTY".
std::string faceStatus(const FaceMark& mark);

// The width of the labelled view: the cross's, or wider where the legend (`title`, then a line a
// face) needs it, so that small faces (a probe-lit figure's 32 texels) do not cut the legend off.
int labelledCrossWidth(const CrossGeometry& g, const std::array<FaceMark, 6>& marks,
                       const std::string& title);

// The view as one image: six equal squares in GL face order (already converted to RGBA for the
// channel), the marks, and labels when `labels` is on (`title` is drawn above the legend; the view
// is labelledCrossWidth wide, the squares where crossGeometry puts them).
RgbaImage unfoldCross(const CubeFaces& faces, const std::array<FaceMark, 6>& marks, bool labels,
                      const std::string& title);

}  // namespace reflect
