// Exact values of the error metrics on tiny hand-made images.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error_metrics.h"

namespace reflect {
namespace {

RgbaImage solid(int w, int h, uint8_t r, uint8_t g, uint8_t b) {
  RgbaImage image;
  image.width = w;
  image.height = h;
  for (int i = 0; i < w * h; ++i) image.pixels.insert(image.pixels.end(), {r, g, b, 255});
  return image;
}

void setPixel(RgbaImage& image, int x, int y, uint8_t r, uint8_t g, uint8_t b, uint8_t a = 255) {
  uint8_t* p = &image.pixels[(static_cast<size_t>(y) * static_cast<size_t>(image.width) +
                              static_cast<size_t>(x)) *
                             4];
  p[0] = r;
  p[1] = g;
  p[2] = b;
  p[3] = a;
}

TEST(ErrorMetrics, IdenticalImagesGiveZeroErrorAndThePsnrCap) {
  const RgbaImage a = solid(3, 2, 10, 20, 30);
  auto m = imageErrorMetrics(a, a, std::vector<uint8_t>(6, 1));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m.value().pixelCount, 6u);
  EXPECT_EQ(m.value().rmse, 0.0);
  EXPECT_EQ(m.value().psnrDb, kPsnrCapDb);
  EXPECT_EQ(m.value().p95PixelError, 0);
  EXPECT_EQ(m.value().maxPixelError, 0);
}

TEST(ErrorMetrics, TwoByTwoByHand) {
  RgbaImage a = solid(2, 2, 100, 100, 100);
  RgbaImage b = a;
  // Pixel errors (max abs RGB difference): 0, 3, 4, 12. Squared channel differences:
  // (0,0,0), (3,0,0), (0,4,0) and (12,0,0) -> sum 9 + 16 + 144 = 169 over 4 x 3 channels.
  setPixel(b, 1, 0, 103, 100, 100);
  setPixel(b, 0, 1, 100, 96, 100);
  setPixel(b, 1, 1, 88, 100, 100, 0);  // alpha is ignored
  auto m = imageErrorMetrics(a, b, {1, 1, 1, 1});
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m.value().pixelCount, 4u);
  EXPECT_DOUBLE_EQ(m.value().rmse, std::sqrt(169.0 / 12.0));
  EXPECT_DOUBLE_EQ(m.value().psnrDb, 20.0 * std::log10(255.0 / std::sqrt(169.0 / 12.0)));
  EXPECT_EQ(m.value().p95PixelError, 12);  // nearest rank: ceil(0.95 * 4) = 4th smallest
  EXPECT_EQ(m.value().maxPixelError, 12);
  EXPECT_EQ(m.value().visibleErrorPixels, 0u);
}

TEST(ErrorMetrics, VisibleErrorsAreThePixelsOffByMoreThanThirtyTwoLevels) {
  RgbaImage a = solid(3, 1, 100, 100, 100);
  RgbaImage b = a;
  setPixel(b, 0, 0, 132, 100, 100);  // 32: not more than the threshold
  setPixel(b, 1, 0, 100, 67, 100);   // 33
  setPixel(b, 2, 0, 100, 100, 0);    // 100
  auto m = imageErrorMetrics(a, b, {1, 1, 1});
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m.value().visibleErrorPixels, 2u);
  m = imageErrorMetrics(a, b, {1, 1, 0});
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m.value().visibleErrorPixels, 1u);  // only masked pixels count
}

TEST(ErrorMetrics, TheMaskSelectsThePixels) {
  RgbaImage a = solid(2, 2, 0, 0, 0);
  RgbaImage b = a;
  setPixel(b, 0, 0, 255, 255, 255);  // masked out
  setPixel(b, 1, 0, 0, 6, 0);
  setPixel(b, 0, 1, 6, 6,
           6);  // RMSE over 2 pixels x 3 channels: sqrt((36 + 3 x 36) / 6) = sqrt(24)
  auto m = imageErrorMetrics(a, b, {0, 1, 1, 0});
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m.value().pixelCount, 2u);
  EXPECT_DOUBLE_EQ(m.value().rmse, std::sqrt(24.0));
  EXPECT_EQ(m.value().maxPixelError, 6);
  EXPECT_EQ(m.value().p95PixelError, 6);
}

TEST(ErrorMetrics, NinetyFifthPercentileIsTheNearestRank) {
  // 20 pixels with errors 1..20: ceil(0.95 x 20) = 19th smallest = 19.
  RgbaImage a = solid(20, 1, 0, 0, 0);
  RgbaImage b = a;
  for (int x = 0; x < 20; ++x) setPixel(b, x, 0, 0, 0, static_cast<uint8_t>(x + 1));
  auto m = imageErrorMetrics(a, b, std::vector<uint8_t>(20, 1));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m.value().p95PixelError, 19);
  EXPECT_EQ(m.value().maxPixelError, 20);
  // Sum of squares 1..20 = 2870 over 60 channels.
  EXPECT_DOUBLE_EQ(m.value().rmse, std::sqrt(2870.0 / 60.0));
}

TEST(ErrorMetrics, FullScaleDifferenceIsZeroDecibels) {
  auto m = imageErrorMetrics(solid(1, 1, 0, 0, 0), solid(1, 1, 255, 255, 255), {1});
  ASSERT_TRUE(m) << m.error();
  EXPECT_DOUBLE_EQ(m.value().rmse, 255.0);
  EXPECT_DOUBLE_EQ(m.value().psnrDb, 0.0);
}

TEST(ErrorMetrics, EmptyMaskCountsNothing) {
  auto m = imageErrorMetrics(solid(2, 1, 0, 0, 0), solid(2, 1, 9, 9, 9), {0, 0});
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m.value().pixelCount, 0u);
  EXPECT_EQ(m.value().rmse, 0.0);
  EXPECT_EQ(m.value().psnrDb, kPsnrCapDb);
}

TEST(ErrorMetrics, MismatchedSizesAndMasksFail) {
  EXPECT_FALSE(imageErrorMetrics(solid(2, 1, 0, 0, 0), solid(1, 2, 0, 0, 0), {1, 1}));
  EXPECT_FALSE(imageErrorMetrics(solid(2, 1, 0, 0, 0), solid(2, 1, 0, 0, 0), {1}));
}

TEST(ErrorMetrics, PsnrFromRmse) {
  EXPECT_EQ(psnrFromRmse(0.0), kPsnrCapDb);
  EXPECT_DOUBLE_EQ(psnrFromRmse(25.5), 20.0);
  EXPECT_EQ(psnrFromRmse(1e-9), kPsnrCapDb);  // capped, not 200 dB
}

TEST(AngularError, ExactAngles) {
  const std::vector<glm::vec3> a{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}};
  const std::vector<glm::vec3> b{
      {1, 0, 0}, {1, 0, 0}, {0, 0, -1}, glm::normalize(glm::vec3(1, 1, 0))};
  // 0, 90, 180 and 45 degrees: mean 78.75.
  auto mean = meanAngularErrorDegrees(a, b);
  ASSERT_TRUE(mean) << mean.error();
  EXPECT_NEAR(mean.value(), 78.75, 1e-9);
}

TEST(AngularError, SmallAnglesKeepTheirPrecision) {
  const float angle = 1e-4f;  // radians; acos of the dot product would lose it in float
  const std::vector<glm::vec3> a{{1, 0, 0}};
  const std::vector<glm::vec3> b{{std::cos(angle), std::sin(angle), 0}};
  auto mean = meanAngularErrorDegrees(a, b);
  ASSERT_TRUE(mean) << mean.error();
  EXPECT_NEAR(mean.value(), glm::degrees(static_cast<double>(angle)), 1e-7);
}

TEST(AngularError, EmptyListsAndMismatchedLengths) {
  auto empty = meanAngularErrorDegrees({}, {});
  ASSERT_TRUE(empty);
  EXPECT_EQ(empty.value(), 0.0);
  EXPECT_FALSE(meanAngularErrorDegrees({{1, 0, 0}}, {}));
}

}  // namespace
}  // namespace reflect
