// Long run times and tiny sizes: the clock after 1e6 seconds (and past any sensible time), the
// frame at t = 1e6 against t = 0, a 1 x 1 frame, a 1-texel cube map, and face sizes the cube
// target has to clamp.
#include <gtest/gtest.h>

#include <GLES3/gl31.h>

#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "app/headless_frames.h"
#include "core/animation_clock.h"
#include "extremes_util.h"
#include "gl_fixture.h"

namespace reflect {
namespace {

using extremes::rgbAt;
using extremes::toBytes;

TEST(TimeExtremes, ClockWrapsExactlyAfterAMillionSeconds) {
  AnimationClock clock;
  clock.set(1e6);  // 27e6 degrees = 75000 turns
  EXPECT_EQ(clock.orbitDegrees(), 0.0);
  clock.set(1e6 + 1.0);
  EXPECT_EQ(clock.orbitDegrees(), 27.0);
  clock.set(1e6 + 1.0 / 3.0);
  EXPECT_NEAR(clock.orbitDegrees(), 9.0, 1e-8);
  clock.set(-5.0);
  EXPECT_EQ(clock.orbitDegrees(), 225.0);
  for (double t : {1e9, 1e12, 1e15, 1e18, 1e300, -1e300}) {
    clock.set(t);
    const double a = clock.orbitDegrees();
    EXPECT_TRUE(std::isfinite(a) && a >= 0.0 && a < 360.0) << "t = " << t << ": " << a;
  }
}

TEST(TimeExtremes, ClockAngleIsAlwaysFiniteEvenPastAnySensibleTime) {
  // seconds x 27 overflows to infinity above DBL_MAX / 27 (6.7e306), and fmod(inf, 360) is NaN:
  // a NaN orbit angle makes every orbiting model matrix NaN. `reflect render --time 1e307`
  // reaches it. Such times must be refused like non-finite ones.
  AnimationClock clock;
  clock.set(1e307);
  EXPECT_TRUE(std::isfinite(clock.orbitDegrees())) << clock.orbitDegrees();
  clock.set(std::numeric_limits<double>::max());
  EXPECT_TRUE(std::isfinite(clock.orbitDegrees())) << clock.orbitDegrees();
  AnimationClock stepped;
  stepped.set(1e306);
  stepped.advance(std::numeric_limits<double>::max());
  stepped.advance(std::numeric_limits<double>::max());
  EXPECT_TRUE(std::isfinite(stepped.orbitDegrees())) << stepped.orbitDegrees();
}

TEST(TimeExtremes, SteppingAMillionSecondsAt60HzDriftsLessThanATenthOfADegree) {
  // 6e7 frames of 1/60 s added one by one: each addition rounds at the clock's magnitude, so the
  // summed time drifts from the ideal (the angle itself follows the summed time exactly).
  AnimationClock clock;
  constexpr int kFrames = 60'000'000;
  for (int i = 0; i < kFrames; ++i) clock.advance(1.0 / 60.0);
  const double timeError = clock.seconds() - 1e6;
  const double drift =
      clock.orbitDegrees() > 180.0 ? clock.orbitDegrees() - 360.0 : clock.orbitDegrees();
  std::printf("after 6e7 steps of 1/60 s: t off by %.3g s, orbit %.4g degrees off the exact 0\n",
              timeError, drift);
  EXPECT_LT(std::fabs(timeError), 0.01);
  EXPECT_LT(std::fabs(drift), 0.1);
  EXPECT_NEAR(drift, timeError * AnimationClock::kOrbitDegreesPerSecond, 1e-6);
}

TEST(TimeExtremes, FrameAtAMillionSecondsEqualsFrameAtZero) {
  constexpr int kSize = 128;
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  PlannerSettings everyFrame;
  everyFrame.policy = UpdatePolicy::EveryFrame;  // recapture every face for every frame
  demo->setPlannerSettings(everyFrame);
  auto at0 = renderFrameAt(*demo, 0.0, kSize, kSize);
  auto at1 = renderFrameAt(*demo, 1.0, kSize, kSize);
  auto atMillion = renderFrameAt(*demo, 1e6, kSize, kSize);
  auto atMillionAnd1 = renderFrameAt(*demo, 1e6 + 1.0, kSize, kSize);
  ASSERT_TRUE(at0 && at1 && atMillion && atMillionAnd1);
  EXPECT_EQ(demo->lastStats().orbitDegrees, 27.0);
  EXPECT_EQ(atMillion.value().pixels, at0.value().pixels);
  EXPECT_EQ(atMillionAnd1.value().pixels, at1.value().pixels);
  EXPECT_NE(at1.value().pixels, at0.value().pixels);  // the figures did move in one second
}

TEST(SizeExtremes, OneByOneFrameIsTheCentrePixelOfALargeOne) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  auto tiny = renderFrameAt(*demo, 0.0, 1, 1);
  ASSERT_TRUE(tiny) << tiny.error();
  // An odd size puts a pixel centre exactly on the view axis, as the single pixel's is.
  auto large = renderFrameAt(*demo, 0.0, 255, 255);
  ASSERT_TRUE(large);
  const glm::u8vec3 one = rgbAt(tiny.value(), 0, 0);
  const glm::u8vec3 centre = rgbAt(large.value(), 127, 127);
  std::printf("1x1 frame %s, centre of 255x255 %s\n", extremes::describe(one).c_str(),
              extremes::describe(centre).c_str());
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(one[c]), int(centre[c]), 2);
  EXPECT_NE(one, glm::u8vec3(0));
}

// The cube target's real face size (ES 3.1's query; the project itself stays within ES 3.0).
int textureFaceSize(GLuint cube) {
  GLint size = 0;
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_TEXTURE_WIDTH, &size);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  return size;
}

TEST(SizeExtremes, OneTexelCubeMapRendersAFiniteMirror) {
  Scene scene = makeDynamicReflectionScene();
  auto demo = testing::makeCapturingDemo(scene);
  ASSERT_EQ(demo->setCubeFaceSize(1), "");
  ASSERT_EQ(demo->initGraphics(), "");
  auto image = renderFrameAt(*demo, 0.0, 65, 65);
  ASSERT_TRUE(image) << image.error();
  EXPECT_EQ(demo->lastStats().cubeFaceSize, 1);
  EXPECT_EQ(textureFaceSize(demo->environmentTexture()), 1);
  // The mirror's centre pixel: at least the base colour's share, and not black.
  const glm::u8vec3 c = rgbAt(image.value(), 32, 32);
  const glm::u8vec3 floor = toBytes(0.3f * glm::vec3(0.95f, 0.85f, 0.4f)) - glm::u8vec3(1);
  EXPECT_FALSE(glm::any(glm::lessThan(c, floor))) << extremes::describe(c);
}

TEST(SizeExtremes, CubeSizeOutsideTheLimitsIsClampedAndReported) {
  GLint maxCube = 0;
  glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &maxCube);
  std::printf("GL_MAX_CUBE_MAP_TEXTURE_SIZE = %d; Demo::kMaxCubeFaceSize = %d\n", maxCube,
              Demo::kMaxCubeFaceSize);
  // The stats must report the face size the cube map really has. Above the limit the clamp
  // would allocate 6 x 4096^2 x 4 bytes (400 MB): only the message is checked there.
  Scene scene;
  scene.clearColour = glm::vec3(0.2f, 0.4f, 0.6f);
  scene.objects.push_back(extremes::mirrorObject(
      "sphere.obj", glm::scale(glm::mat4(1.0f), glm::vec3(0.5f)), {1, 1, 1}));
  {
    Demo unrendered(scene);
    EXPECT_NE(unrendered.setCubeFaceSize(Demo::kMaxCubeFaceSize + 1), "");
    EXPECT_NE(unrendered.setCubeFaceSize(1 << 30), "");
    EXPECT_EQ(unrendered.setCubeFaceSize(Demo::kMaxCubeFaceSize), "");
  }
  for (int requested : {0, -7}) {
    auto demo = testing::makeCapturingDemo(scene);
    EXPECT_NE(demo->setCubeFaceSize(requested), "") << "no message for face size " << requested;
    ASSERT_EQ(demo->initGraphics(), "");
    ASSERT_TRUE(renderFrameAt(*demo, 0.0, 16, 16));
    const int used = textureFaceSize(demo->environmentTexture());
    const int reported = demo->lastStats().cubeFaceSize;
    std::printf("face size %d requested: %d used, stats report %d\n", requested, used, reported);
    EXPECT_EQ(used, 1) << "requested " << requested;
    EXPECT_EQ(reported, used) << "requested " << requested;
  }
}

TEST(SizeExtremes, ClampedCubeTargetKeepsTheFacesItAlreadyCaptured) {
  // SceneRenderer::capture recreates a probe's target whenever its format differs from the one
  // the scene asks for. Were a clamped size ever to reach it, they would differ on every frame,
  // and each frame that redraws some faces would recreate the cube and lose the faces it did not
  // redraw. Time-sliced capture (two faces a frame) would show it within three frames.
  Scene scene;
  scene.clearColour = glm::vec3(0.2f, 0.4f, 0.6f);
  SceneObject sphere =
      extremes::mirrorObject("sphere.obj", glm::scale(glm::mat4(1.0f), glm::vec3(0.5f)), {1, 1, 1});
  scene.objects.push_back(sphere);
  std::vector<glm::vec3> faceCentres;
  for (int face = 0; face < 6; ++face) {
    glm::vec3 d(0.0f);
    d[face / 2] = face % 2 == 0 ? 1.0f : -1.0f;
    faceCentres.push_back(d);
  }
  PlannerSettings sliced;
  sliced.policy = UpdatePolicy::TimeSliced;
  sliced.facesPerFrame = 2;
  std::map<int, int> facesRight;
  for (int requested : {1, 0}) {
    auto demo = testing::makeCapturingDemo(scene);
    demo->setPlannerSettings(sliced);
    demo->setCubeFaceSize(requested);
    ASSERT_EQ(demo->initGraphics(), "");
    for (int frame = 0; frame < 3; ++frame) ASSERT_TRUE(renderFrameAt(*demo, 0.0, 16, 16));
    int right = 0;
    for (const glm::u8vec3& c : extremes::sampleCube(demo->environmentTexture(), faceCentres)) {
      right += c == glm::u8vec3(51, 102, 153);
    }
    facesRight[requested] = right;
    std::printf(
        "face size %d, time-sliced 2 faces a frame, after 3 frames: %d of 6 faces hold the scene\n",
        requested, right);
  }
  EXPECT_EQ(facesRight[1], 6);
  EXPECT_EQ(facesRight[0], 6) << "a clamped face size lost faces captured on earlier frames";
}

}  // namespace
}  // namespace reflect
