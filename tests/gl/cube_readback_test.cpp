// The faces view reads the probe back face by face: each image texel must be what
// texture(cube, d) returns along that texel's direction (so the cross shows the cube map the
// mirrors read, the right way up), distances must be the stored codes as grey, and a channel the
// probe does not hold is refused with the setting it needs.
#include <gtest/gtest.h>

#include <cstring>

#include "core/cube_sampling.h"
#include "cube_sampler.h"
#include "gfx/cube_readback.h"
#include "gfx/image_blit.h"
#include "gfx/offscreen_target.h"
#include "gl_fixture.h"

namespace reflect {
namespace {

constexpr int kSize = 8;

// Face f cleared to a colour of its own with depth code 1000 (f + 1); the quadrant of texels
// i, j < 4 (window y < 4: the rows the face addresses first) cleared to the inverse colour and
// code 40000 + f, so that a flip or a mirror of the read-back shows.
void paintFaces(const CubeCaptureTarget& target, int layer) {
  for (int face = 0; face < 6; ++face) {
    target.bindFace(face, layer);
    const float base[3] = {0.1f * static_cast<float>(face + 1), 0.2f * static_cast<float>(layer),
                           0.5f};
    const unsigned codes[2] = {1000u * static_cast<unsigned>(face + 1), 60000u};
    target.clearFace(base, 1.0f, codes);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, kSize / 2, kSize / 2);
    const float corner[3] = {1.0f - base[0], 1.0f - base[1], 0.0f};
    const unsigned cornerCodes[2] = {40000u + static_cast<unsigned>(face), 60000u};
    target.clearFace(corner, 1.0f, cornerCodes);
    glDisable(GL_SCISSOR_TEST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

CubeCaptureTarget makeTarget(bool depthChain, int layers) {
  CaptureFormat format;
  format.faceSize = kSize;
  format.depthChain = depthChain;
  format.layers = layers;
  Result<CubeCaptureTarget> target = CubeCaptureTarget::create(format);
  EXPECT_TRUE(target) << target.error();
  return std::move(target.value());
}

// Every texel of every face against texture(cube, direction of the texel's centre).
void expectFacesAreWhatTheCubeReturns(GLuint cube, const CubeFaces& faces) {
  std::vector<glm::vec3> directions;
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j < kSize; ++j) {
      for (int i = 0; i < kSize; ++i) {
        directions.push_back(faceDirection(face, (static_cast<float>(i) + 0.5f) / kSize,
                                           (static_cast<float>(j) + 0.5f) / kSize));
      }
    }
  }
  const std::vector<glm::u8vec3> sampled = testing::sampleCube(cube, directions);
  ASSERT_EQ(sampled.size(), directions.size());
  size_t k = 0;
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j < kSize; ++j) {
      for (int i = 0; i < kSize; ++i, ++k) {
        const uint8_t* got = faces[static_cast<size_t>(face)].at(i, j);
        for (int c = 0; c < 3; ++c) {
          ASSERT_EQ(got[c], sampled[k][c]) << "face " << face << " texel " << i << "," << j;
        }
      }
    }
  }
}

TEST(CubeReadback, EachTexelIsWhatTheCubeReturnsAlongItsDirection) {
  const CubeCaptureTarget target = makeTarget(true, 2);
  paintFaces(target, 0);
  paintFaces(target, 1);
  const Result<CubeFaces> colour = readCubeFaces(target, FacesChannel::Colour);
  ASSERT_TRUE(colour) << colour.error();
  expectFacesAreWhatTheCubeReturns(target.texture(0), colour.value());
  const Result<CubeFaces> second = readCubeFaces(target, FacesChannel::SecondLayer);
  ASSERT_TRUE(second) << second.error();
  expectFacesAreWhatTheCubeReturns(target.texture(1), second.value());
  // The two layers differ (green is 0.2 x layer), so the second really is layer 1.
  EXPECT_NE(colour.value()[0].pixels, second.value()[0].pixels);
  EXPECT_TRUE(checkGlError("CubeReadback"));
}

TEST(CubeReadback, DistanceIsTheStoredNearCodeAsGreyNearBright) {
  const CubeCaptureTarget target = makeTarget(true, 1);
  paintFaces(target, 0);
  const Result<CubeFaces> distance = readCubeFaces(target, FacesChannel::Distance);
  ASSERT_TRUE(distance) << distance.error();
  for (int face = 0; face < 6; ++face) {
    const RgbaImage& image = distance.value()[static_cast<size_t>(face)];
    const unsigned code = 1000u * static_cast<unsigned>(face + 1);
    const unsigned corner = 40000u + static_cast<unsigned>(face);
    EXPECT_EQ(image.at(6, 6)[0], 255 - (code * 255 + 32767) / 65535) << "face " << face;
    EXPECT_EQ(image.at(1, 2)[0], 255 - (corner * 255 + 32767) / 65535) << "face " << face;
    EXPECT_EQ(image.at(1, 2)[1], image.at(1, 2)[0]);
    EXPECT_EQ(image.at(1, 2)[3], 255);
  }
}

TEST(CubeReadback, AChannelTheProbeDoesNotStoreNamesTheSettingItNeeds) {
  const CubeCaptureTarget plain = makeTarget(false, 1);
  const Result<CubeFaces> distance = readCubeFaces(plain, FacesChannel::Distance);
  ASSERT_FALSE(distance);
  EXPECT_EQ(distance.error(),
            "the distance channel needs stored depths: set search to hierarchical");
  const Result<CubeFaces> second = readCubeFaces(plain, FacesChannel::SecondLayer);
  ASSERT_FALSE(second);
  EXPECT_EQ(
      second.error(),
      "the second-layer channel needs a second layer: set search to hierarchical and layers to 2");
}

TEST(CubeReadback, TheViewOnScreenIsTheCrossOfTheReadBackPixelForPixel) {
  const CubeCaptureTarget target = makeTarget(true, 1);
  paintFaces(target, 0);
  const Result<CubeFaces> faces = readCubeFaces(target, FacesChannel::Colour);
  ASSERT_TRUE(faces) << faces.error();
  std::array<FaceMark, 6> marks;
  for (FaceMark& mark : marks) mark.captured = true;
  const RgbaImage cross = unfoldCross(faces.value(), marks, true, "COLOUR");
  Result<ImageBlit> blit = ImageBlit::create();
  ASSERT_TRUE(blit) << blit.error();
  // A screen two pixels wider and taller: the cross centred, one pixel of background around it.
  Result<OffscreenTarget> screen = OffscreenTarget::create(cross.width + 2, cross.height + 2);
  ASSERT_TRUE(screen) << screen.error();
  glBindFramebuffer(GL_FRAMEBUFFER, screen.value().framebuffer());
  blit.value().draw(cross, cross.width + 2, cross.height + 2, kCrossBackground);
  const RgbaImage shown = screen.value().readPixels();
  for (int y = 0; y < cross.height; ++y) {
    ASSERT_EQ(std::memcmp(shown.at(1, y + 1), cross.at(0, y), static_cast<size_t>(cross.width) * 4),
              0)
        << "row " << y;
  }
  EXPECT_EQ(std::memcmp(shown.at(0, 0), kCrossBackground.data(), 4), 0);
  // And the face squares in it are the read-back's pixels.
  const CrossGeometry g = crossGeometry(kSize);
  EXPECT_EQ(std::memcmp(shown.at(g.squareOrigin[3][0] + 1, g.squareOrigin[3][1] + 1),
                        faces.value()[3].at(0, 0), 4),
            0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  EXPECT_TRUE(checkGlError("ImageBlit"));
}

}  // namespace
}  // namespace reflect
