// The live error view's numbers (show error): the GPU compares the current mode's frame with the
// exact mode's and writes, per pixel, the absolute difference of R, G and B and in alpha 255 on a
// reflector (mirror or glass) pixel, 0 elsewhere. This sums that read-back. No GL.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/error_metrics.h"

namespace reflect {

// A pixel is "off" when one of its channels differs by more than this many levels.
inline constexpr int kErrorViewThreshold = 32;

struct ErrorViewStats {
  size_t reflectorPixels = 0;
  double rmse = 0.0;               // over R, G and B of the reflector pixels, 0..255
  double psnrDb = kPsnrCapDb;      // kPsnrCapDb when identical (an infinite PSNR)
  size_t pixelsOverThreshold = 0;  // reflector pixels off by more than kErrorViewThreshold
  int maxError = 0;
  bool exact() const { return rmse == 0.0; }
};

ErrorViewStats summariseErrorImage(const std::vector<uint8_t>& rgba);

}  // namespace reflect
