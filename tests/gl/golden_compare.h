// Rendered frames against golden PNGs in tests/golden. A golden is held twice: over the whole
// frame, and inside its reflectors' pixels (the mirrors and glass are a small part of a frame, and
// what they show could change a lot there and little in the frame's mean).
// REFLECT_UPDATE_GOLDEN=1 rewrites them, printing each image's difference from the old one first.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/scene.h"

namespace reflect::testing {

// The whole frame. The renderer is deterministic on one Mesa version (the difference is 0 here);
// these leave room for another llvmpipe's rounding, and are far below what a moved object, a
// flipped face or a missing reflection changes (thousands of pixels by more than 100 levels).
inline constexpr int kPixelTolerance = 16;         // per channel, 0..255
inline constexpr double kMaxFractionOver = 0.002;  // of pixels beyond the tolerance
inline constexpr double kMaxMeanDifference = 0.5;  // mean absolute channel difference
// Inside the reflectors: the same tolerance and share of pixels beyond it, and a mean difference
// low enough that a mirror whose reflection weight goes from 0.78 to 0.70 fails (its reflection
// darkens by 8% of what it reflects: 8 to 20 levels a channel over the mirror).
inline constexpr double kMaxReflectorFractionOver = 0.002;
inline constexpr double kMaxReflectorMeanDifference = 1.0;

// Which pixels of a frame show a reflector (mirror, glass, or Ex12-1's cube-textured object:
// true), seen as the camera sees them (what stands in front of one hides it): the scene drawn
// with its reflectors flat white, everything else flat black, at the same time and size. Empty
// when the scene has none.
std::vector<bool> reflectorMask(const Scene& scene, double seconds, int width, int height);

struct GoldenDifference {
  ImageDifference frame;
  std::optional<ImageDifference> reflectors;  // none when the frame shows no reflector
  size_t reflectorPixels = 0;
};
// `image` against `golden` (same size), over the frame and inside `mask` (may be empty).
GoldenDifference goldenDifference(const RgbaImage& image, const RgbaImage& golden,
                                  const std::vector<bool>& mask);

// Holds `image` to tests/golden/`name` over the frame and inside `mask` (a frame's
// reflectorMask; empty: the frame alone).
void expectMatchesGolden(const RgbaImage& image, const std::string& name,
                         const std::vector<bool>& mask = {});

}  // namespace reflect::testing
