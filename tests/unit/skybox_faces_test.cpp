#include <gtest/gtest.h>

#include "core/skybox_faces.h"

namespace reflect {
namespace {

RgbaImage image(int w, int h, uint8_t value = 0) {
  return RgbaImage{
      w, h, std::vector<uint8_t>(static_cast<size_t>(w) * static_cast<size_t>(h) * 4, value)};
}

const std::array<std::string, 6> kNames = {"px.png", "nx.png", "py.png",
                                           "ny.png", "pz.png", "nz.png"};

TEST(SkyboxFaces, SuffixPaths) {
  EXPECT_EQ(skyboxSuffixPaths("sky/day.png")[0], "sky/day_px.png");
  EXPECT_EQ(skyboxSuffixPaths("sky/day.png")[3], "sky/day_ny.png");
  EXPECT_EQ(skyboxSuffixPaths("sky.v2/day")[5], "sky.v2/day_nz.png");
}

TEST(SkyboxFaces, SixEqualSquaresAreAccepted) {
  std::vector<RgbaImage> six(6, image(8, 8));
  auto faces = facesFromImages(six, kNames);
  ASSERT_TRUE(faces) << faces.error();
  EXPECT_EQ(faces.value()[5].width, 8);
}

TEST(SkyboxFaces, WrongShapesAndSizesAreNamed) {
  std::vector<RgbaImage> six(6, image(8, 8));
  six[2] = image(8, 4);
  EXPECT_EQ(facesFromImages(six, kNames).error(),
            "py.png: a cube face must be square, this image is 8x4");
  six[2] = image(16, 16);
  EXPECT_EQ(facesFromImages(six, kNames).error(),
            "py.png: is 16x16 but px.png is 8x8; all six faces must be the same size");
  EXPECT_EQ(facesFromImages(std::vector<RgbaImage>(5, image(8, 8)), kNames).error(),
            "a skybox needs 6 images, got 5");
}

TEST(SkyboxFaces, CrossIsSplitIntoTheRightCells) {
  RgbaImage cross = image(8, 6);
  // Mark each cell's top-left pixel with its face index + 1.
  const int cells[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};
  for (int f = 0; f < 6; ++f)
    cross.pixels[(static_cast<size_t>(cells[f][1] * 2) * 8 + static_cast<size_t>(cells[f][0] * 2)) *
                 4] = static_cast<uint8_t>(f + 1);
  auto faces = facesFromCross(cross, "cross.png");
  ASSERT_TRUE(faces) << faces.error();
  for (int f = 0; f < 6; ++f) {
    EXPECT_EQ(faces.value()[static_cast<size_t>(f)].width, 2);
    EXPECT_EQ(faces.value()[static_cast<size_t>(f)].pixels[0], f + 1) << f;
  }
  EXPECT_EQ(
      facesFromCross(image(8, 8), "square.png").error(),
      "square.png: a horizontal cross must be 4:3 with whole squares (4n x 3n), this image is 8x8");
}

}  // namespace
}  // namespace reflect
