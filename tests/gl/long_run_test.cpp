// A long run: 100,000 frames of the animated default scene must not grow memory or the number of
// live GL objects (counted by the RAII handles). Small frames keep it to about a minute.
#include <gtest/gtest.h>

#include <fstream>

#include "app/headless_frames.h"
#include "gfx/gl_handle.h"
#include "gfx/offscreen_target.h"
#include "gl_fixture.h"

namespace reflect {
namespace {

long residentKilobytes() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmRSS:") {
      long kb = 0;
      status >> kb;
      return kb;
    }
  }
  return -1;
}

TEST(LongRun, HundredThousandFramesKeepMemoryAndGlObjectsFlat) {
  Scene scene = makeDynamicReflectionScene();
  scene.capture.faceSize = 8;
  auto demo = testing::makeDemo(scene);
  auto target = OffscreenTarget::create(16, 16);
  ASSERT_TRUE(target) << target.error();
  constexpr int kFrames = 100'000;
  // Mesa's llvmpipe grows by about 100 MB over the first few thousand frames (its JIT and state
  // caches fill), then stays flat; the measurement starts after that.
  constexpr int kWarmup = 5'000;
  long objectsAfterWarmup = 0, rssAfterWarmup = 0;
  for (int i = 0; i < kFrames; ++i) {
    const FrameStats& s = demo->frame(1.0 / 60.0, target.value().framebuffer(), 16, 16, false);
    ASSERT_TRUE(s.error.empty()) << s.error;
    if (i == kWarmup) {
      objectsAfterWarmup = gLiveGlObjects;
      rssAfterWarmup = residentKilobytes();
    }
  }
  glFinish();
  EXPECT_TRUE(checkGlError("long run"));
  EXPECT_EQ(gLiveGlObjects, objectsAfterWarmup);
  const long rssGrowth = residentKilobytes() - rssAfterWarmup;
  std::printf("live GL objects %ld; resident memory grew %ld kB over %d frames\n", gLiveGlObjects,
              rssGrowth, kFrames - kWarmup);
  // 2 MB over 95,000 frames is 22 bytes a frame: far below any per-frame leak of a buffer,
  // texture, query or mesh.
  EXPECT_LT(rssGrowth, 2048);
}

}  // namespace
}  // namespace reflect
