// The default scene (Ex12-2) rendered headless at fixed times: against a golden PNG, and checked
// for what a person looks for: mario's red and sonic's green reflected where they must be.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "app/headless_frames.h"
#include "gl_fixture.h"
#include "golden_compare.h"

namespace reflect {
namespace {

constexpr int kSize = 512;

TEST(DefaultScene, MatchesGoldenAtTwoTimes) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  for (double t : {0.0, 5.0}) {
    auto image = renderFrameAt(*demo, t, kSize, kSize);
    ASSERT_TRUE(image) << image.error();
    testing::expectMatchesGolden(
        image.value(), "ex12_2_t" + std::to_string(static_cast<int>(t)) + ".png",
        testing::reflectorMask(makeDynamicReflectionScene(), t, kSize, kSize));
  }
}

TEST(DefaultScene, FrameStatsCountTheWork) {
  // The default (search: planned) traces the mirror here: no probe, no face is counted.
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  ASSERT_TRUE(renderFrameAt(*demo, 1.0, 64, 64));
  const FrameStats& s = demo->lastStats();
  EXPECT_EQ(s.tracedReflectors, 1);
  EXPECT_EQ(s.facesCaptured, 0);
  EXPECT_EQ(s.probes, 0);
  EXPECT_EQ(s.captureDrawCalls, 0);
  EXPECT_EQ(s.mainDrawCalls, 4);
}

TEST(DefaultScene, CapturedFrameStatsCountTheWork) {
  auto demo = testing::makeCapturingDemo(makeDynamicReflectionScene());
  ASSERT_TRUE(renderFrameAt(*demo, 1.0, 64, 64));
  const FrameStats& s = demo->lastStats();
  EXPECT_EQ(s.facesCaptured, 6);  // the first frame captures every face
  EXPECT_EQ(s.probes, 1);
  EXPECT_EQ(s.tracedReflectors, 0);
  EXPECT_EQ(s.mainDrawCalls, 4);
  EXPECT_EQ(s.cubeFaceSize, 256);
  EXPECT_GT(s.triangles(), 0u);
  EXPECT_GE(s.frameMs, s.captureMs);
  EXPECT_DOUBLE_EQ(s.orbitDegrees, 27.0);
}

TEST(DefaultScene, GpuTimerQueriesReportPassTimesNatively) {
  // Mesa offers GL_EXT_disjoint_timer_query; results arrive a few frames late.
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  FrameStats last;
  for (int i = 0; i < 8; ++i) {
    auto image = renderFrameAt(*demo, 0.1 * i, 64, 64);
    ASSERT_TRUE(image);
    last = demo->lastStats();
  }
  EXPECT_GT(last.gpuFrameMs, 0.0);
  EXPECT_GE(last.gpuFrameMs, last.gpuCaptureMs);
  EXPECT_GT(last.gpuCaptureMs, 0.0);  // time 0.1 s steps move the figures: faces are redrawn
}

// Where on screen the mirror shows direction `toward` (from the sphere centre): the sphere point
// whose normal halves the angle between the eye and that direction.
glm::ivec2 reflectionPixel(const glm::vec3& toward, const LookCamera& camera) {
  const glm::vec3 centre(0.0f, 0.25f, 0.0f);
  const float radius = 2.5456f * 0.5f;
  const glm::vec3 n =
      glm::normalize(glm::normalize(camera.eye() - centre) + glm::normalize(toward - centre));
  const glm::vec4 clip =
      camera.projection(1.0f) * camera.view() * glm::vec4(centre + radius * n, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {static_cast<int>((ndc.x * 0.5f + 0.5f) * kSize),
          static_cast<int>((0.5f - ndc.y * 0.5f) * kSize)};
}

// Counts pixels within `radius` of `p` where `channel` beats the other two by `margin`.
int countDominant(const RgbaImage& image, glm::ivec2 p, int radius, int channel, int margin) {
  int count = 0;
  for (int y = p.y - radius; y <= p.y + radius; ++y) {
    for (int x = p.x - radius; x <= p.x + radius; ++x) {
      if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
      const uint8_t* px = image.at(x, y);
      const int other = channel == 0 ? px[1] : px[0];
      if (px[channel] - other > margin) ++count;
    }
  }
  return count;
}

TEST(DefaultScene, SphereReflectsMarioRedAndSonicGreenWhereTheyMustBe) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  for (double t : {0.0, 3.0}) {
    auto image = renderFrameAt(*demo, t, kSize, kSize);
    ASSERT_TRUE(image) << image.error();
    testing::saveOutput(image.value(),
                        "reflection_t" + std::to_string(static_cast<int>(t)) + ".png");
    const float a = glm::radians(27.0f * static_cast<float>(t));
    const glm::mat4 orbit = glm::rotate(glm::mat4(1.0f), a, glm::vec3(0, 1, 0));
    // Figure centres: their placements plus their bounding-box centres in world units.
    const glm::vec3 mario(orbit * glm::vec4(2.5f - 0.04f, -0.5f - 0.05f, 1.5f - 0.01f, 1.0f));
    const glm::vec3 sonic(orbit * glm::vec4(-2.0f + 0.09f, -0.5f + 0.77f, 2.0f - 0.17f, 1.0f));
    const glm::ivec2 marioPixel = reflectionPixel(mario, demo->camera());
    const glm::ivec2 sonicPixel = reflectionPixel(sonic, demo->camera());
    // The mirror shows the figures' unlit sides (the light is behind the camera), so their
    // reflections are dark: 0.78 x 0.2 x figure colour + 0.3 x gold. Over the grey or blue
    // reflection the gold base gives red - green = +8 levels; mario's reflection gives about +32
    // and sonic's green - red about +16. The margins sit between.
    EXPECT_GT(countDominant(image.value(), marioPixel, 10, 0, 20), 10)
        << "no red near (" << marioPixel.x << "," << marioPixel.y << ") at t=" << t;
    EXPECT_GT(countDominant(image.value(), sonicPixel, 10, 1, 6), 10)
        << "no green near (" << sonicPixel.x << "," << sonicPixel.y << ") at t=" << t;
  }
}

}  // namespace
}  // namespace reflect

namespace reflect {
namespace {

TEST(FrameSize, LargerThanTheGlAllowsIsRefusedWithAMessage) {
  // Beyond GL_MAX_VIEWPORT_DIMS / GL_MAX_RENDERBUFFER_SIZE a frame cannot be drawn whole: the
  // CLI and tests get a message instead of a silently cropped picture.
  GLint maxViewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
  GLint maxRenderbuffer = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
  const int allowed = std::min({maxRenderbuffer, maxViewport[0], maxViewport[1]});
  const int tooWide = allowed + 1;
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  auto image = renderFrameAt(*demo, 0.0, tooWide, 4);
  ASSERT_FALSE(image);
  EXPECT_EQ(image.error(), "frame size " + std::to_string(tooWide) + "x4 is outside 1.." +
                               std::to_string(allowed));
  // A 0x0 frame (a hidden tab's canvas) draws nothing and reports no error.
  const FrameStats& stats = demo->frame(1.0 / 60.0, 0, 0, 0, false);
  EXPECT_TRUE(stats.error.empty());
  EXPECT_EQ(stats.facesCaptured, 0);
}

}  // namespace
}  // namespace reflect
