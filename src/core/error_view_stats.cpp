#include "core/error_view_stats.h"

#include <algorithm>
#include <cmath>

namespace reflect {

ErrorViewStats summariseErrorImage(const std::vector<uint8_t>& rgba) {
  ErrorViewStats s;
  double sum = 0.0;
  for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
    if (rgba[i + 3] < 128) continue;
    ++s.reflectorPixels;
    int worst = 0;
    for (size_t c = 0; c < 3; ++c) {
      const int d = rgba[i + c];
      sum += static_cast<double>(d) * d;
      worst = std::max(worst, d);
    }
    s.maxError = std::max(s.maxError, worst);
    if (worst > kErrorViewThreshold) ++s.pixelsOverThreshold;
  }
  if (s.reflectorPixels > 0)
    s.rmse = std::sqrt(sum / (3.0 * static_cast<double>(s.reflectorPixels)));
  s.psnrDb = psnrFromRmse(s.rmse);
  return s;
}

}  // namespace reflect
