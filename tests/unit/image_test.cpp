#include <gtest/gtest.h>

#include "core/image.h"

namespace reflect {
namespace {

RgbaImage solid(int w, int h, uint8_t r, uint8_t g, uint8_t b) {
  RgbaImage image{w, h, {}};
  for (int i = 0; i < w * h; ++i) image.pixels.insert(image.pixels.end(), {r, g, b, 255});
  return image;
}

TEST(Image, CompareReportsMaxMeanAndFraction) {
  RgbaImage a = solid(2, 2, 10, 20, 30);
  RgbaImage b = a;
  b.pixels[0] = 40;  // pixel 0, red +30
  auto d = compareImages(a, b, 10);
  ASSERT_TRUE(d);
  EXPECT_EQ(d.value().maxChannel, 30);
  EXPECT_DOUBLE_EQ(d.value().meanChannel, 30.0 / 12.0);
  EXPECT_DOUBLE_EQ(d.value().fractionOver, 0.25);
}

TEST(Image, CompareRejectsDifferentSizes) {
  auto d = compareImages(solid(2, 2, 0, 0, 0), solid(3, 2, 0, 0, 0));
  EXPECT_FALSE(d);
  EXPECT_EQ(d.error(), "image sizes differ: 2x2 vs 3x2");
}

TEST(Image, FlipRowsSwapsTopAndBottom) {
  RgbaImage image = solid(1, 3, 0, 0, 0);
  image.pixels[0] = 1;
  image.pixels[8] = 3;
  flipRows(image);
  EXPECT_EQ(image.pixels[0], 3);
  EXPECT_EQ(image.pixels[8], 1);
}

TEST(Image, PngRoundTripAndMissingFileMessage) {
  RgbaImage image = solid(3, 2, 200, 100, 50);
  const std::string path = ::testing::TempDir() + "/round_trip.png";
  ASSERT_EQ(writePng(image, path), "");
  auto back = readPng(path);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back.value().pixels, image.pixels);
  auto missing = readPng("/nonexistent/x.png");
  EXPECT_FALSE(missing);
  EXPECT_EQ(missing.error().rfind("/nonexistent/x.png: cannot read image", 0), 0u);
}

}  // namespace
}  // namespace reflect
