// Image error metrics over a pixel mask, and the mean angle between two lists of directions: what
// the accuracy measurements (raster vs ray-traced reference) report. No GL.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.h"
#include "core/result.h"

namespace reflect {

// PSNR reported for identical pixels (an infinite PSNR), and the largest value ever reported.
inline constexpr double kPsnrCapDb = 99.0;
// A pixel whose largest channel difference exceeds this many levels is an error a viewer sees
// (a speckle, a ghost); the accuracy tables count them beside the mean.
inline constexpr int kVisibleErrorLevels = 32;

struct ImageErrorMetrics {
  size_t pixelCount = 0;  // masked pixels compared
  // Root mean square difference over the R, G and B channels of the masked pixels, 0..255.
  double rmse = 0.0;
  // 20 log10(255 / rmse) in dB, capped at kPsnrCapDb (also when rmse is 0 or no pixel is masked).
  double psnrDb = kPsnrCapDb;
  // Per-pixel error = the largest absolute difference of the pixel's R, G and B channels (0..255).
  // p95 is the nearest-rank 95th percentile of that error over the masked pixels: the smallest
  // value that at least 95% of them do not exceed.
  int p95PixelError = 0;
  int maxPixelError = 0;
  // Masked pixels whose error exceeds kVisibleErrorLevels.
  size_t visibleErrorPixels = 0;
};

// Compares the RGB of `a` and `b` (alpha ignored) over the pixels whose mask entry is non-zero.
// The images must have the same size and the mask one entry per pixel (row-major, top row first).
// An all-zero mask gives pixelCount 0, rmse 0 and the PSNR cap.
Result<ImageErrorMetrics> imageErrorMetrics(const RgbaImage& a, const RgbaImage& b,
                                            const std::vector<uint8_t>& mask);

// PSNR in dB (peak 255) for an RMSE on the 0..255 scale, capped at kPsnrCapDb.
double psnrFromRmse(double rmse);

// Mean over i of the angle between a[i] and b[i], in degrees (0..180). Inputs should be unit
// vectors; they are normalised anyway, and the angle is computed as atan2(|a x b|, a . b) so small
// angles keep their precision. Failure when the lists differ in length; empty lists give 0.
Result<double> meanAngularErrorDegrees(const std::vector<glm::vec3>& a,
                                       const std::vector<glm::vec3>& b);

}  // namespace reflect
