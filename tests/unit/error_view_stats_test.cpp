// core/error_view_stats.h: the error view's read-back summed.
#include <gtest/gtest.h>

#include "core/error_view_stats.h"

namespace reflect {
namespace {

TEST(ErrorViewStats, IdenticalIsInfinitePsnrAndNothingOff) {
  const std::vector<uint8_t> pixels = {0, 0, 0, 255, 0, 0, 0, 255, 9, 9, 9, 0};
  const ErrorViewStats s = summariseErrorImage(pixels);
  EXPECT_EQ(s.reflectorPixels, 2u);
  EXPECT_TRUE(s.exact());
  EXPECT_EQ(s.psnrDb, kPsnrCapDb);
  EXPECT_EQ(s.pixelsOverThreshold, 0u);
}

TEST(ErrorViewStats, CountsAndPsnrOverReflectorsOnly) {
  // A reflector pixel off by 40 in red, one off by 32 exactly, one not a reflector off by 200.
  const std::vector<uint8_t> pixels = {40, 0, 0, 255, 0, 32, 0, 255, 200, 200, 200, 0};
  const ErrorViewStats s = summariseErrorImage(pixels);
  EXPECT_EQ(s.reflectorPixels, 2u);
  EXPECT_EQ(s.pixelsOverThreshold, 1u);
  EXPECT_EQ(s.maxError, 40);
  EXPECT_NEAR(s.rmse, std::sqrt((40.0 * 40.0 + 32.0 * 32.0) / 6.0), 1e-9);
  EXPECT_NEAR(s.psnrDb, 20.0 * std::log10(255.0 / s.rmse), 1e-9);
}

}  // namespace
}  // namespace reflect
