// Rendered frames against golden PNGs in tests/golden (REFLECT_UPDATE_GOLDEN=1 rewrites them).
#pragma once

#include <string>

#include "core/image.h"

namespace reflect::testing {

// Thresholds. The renderer is deterministic on one Mesa version (the difference is 0 here);
// these leave room for another llvmpipe's rounding, and are far below what a moved object, a
// flipped face or a missing reflection changes (thousands of pixels by more than 100 levels).
inline constexpr int kPixelTolerance = 16;         // per channel, 0..255
inline constexpr double kMaxFractionOver = 0.002;  // of pixels beyond the tolerance
inline constexpr double kMaxMeanDifference = 0.5;  // mean absolute channel difference

void expectMatchesGolden(const RgbaImage& image, const std::string& name);

}  // namespace reflect::testing
