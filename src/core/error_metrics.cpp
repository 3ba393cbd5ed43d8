#include "core/error_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

namespace reflect {

double psnrFromRmse(double rmse) {
  if (!(rmse > 0.0)) return kPsnrCapDb;
  return std::min(kPsnrCapDb, 20.0 * std::log10(255.0 / rmse));
}

Result<ImageErrorMetrics> imageErrorMetrics(const RgbaImage& a, const RgbaImage& b,
                                            const std::vector<uint8_t>& mask) {
  if (a.width != b.width || a.height != b.height) {
    return Result<ImageErrorMetrics>::failure(
        "image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
        " and " + std::to_string(b.width) + "x" + std::to_string(b.height));
  }
  const size_t pixels =
      static_cast<size_t>(std::max(a.width, 0)) * static_cast<size_t>(std::max(a.height, 0));
  if (a.pixels.size() != pixels * 4 || b.pixels.size() != pixels * 4) {
    return Result<ImageErrorMetrics>::failure("image pixel buffer does not match its size");
  }
  if (mask.size() != pixels) {
    return Result<ImageErrorMetrics>::failure("mask has " + std::to_string(mask.size()) +
                                              " entries for " + std::to_string(pixels) + " pixels");
  }

  ImageErrorMetrics m;
  std::vector<int> errors;
  double sumSquares = 0.0;
  for (size_t i = 0; i < pixels; ++i) {
    if (mask[i] == 0) continue;
    int pixelError = 0;
    for (size_t c = 0; c < 3; ++c) {
      const int d =
          std::abs(static_cast<int>(a.pixels[i * 4 + c]) - static_cast<int>(b.pixels[i * 4 + c]));
      sumSquares += static_cast<double>(d) * static_cast<double>(d);
      pixelError = std::max(pixelError, d);
    }
    errors.push_back(pixelError);
    if (pixelError > kVisibleErrorLevels) ++m.visibleErrorPixels;
  }
  m.pixelCount = errors.size();
  if (errors.empty()) return m;

  m.rmse = std::sqrt(sumSquares / (3.0 * static_cast<double>(errors.size())));
  m.psnrDb = psnrFromRmse(m.rmse);
  // Nearest rank: the ceil(0.95 n)-th smallest error (1-based).
  const size_t rank = static_cast<size_t>(std::ceil(0.95 * static_cast<double>(errors.size())));
  const size_t index = std::clamp<size_t>(rank, 1, errors.size()) - 1;
  std::nth_element(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(index),
                   errors.end());
  m.p95PixelError = errors[index];
  m.maxPixelError = *std::max_element(errors.begin(), errors.end());
  return m;
}

Result<double> meanAngularErrorDegrees(const std::vector<glm::vec3>& a,
                                       const std::vector<glm::vec3>& b) {
  if (a.size() != b.size()) {
    return Result<double>::failure("direction lists differ in length: " + std::to_string(a.size()) +
                                   " and " + std::to_string(b.size()));
  }
  if (a.empty()) return 0.0;
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    const glm::dvec3 u = glm::normalize(glm::dvec3(a[i]));
    const glm::dvec3 v = glm::normalize(glm::dvec3(b[i]));
    sum += std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
  }
  return glm::degrees(sum / static_cast<double>(a.size()));
}

}  // namespace reflect
