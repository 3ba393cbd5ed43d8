// The exact mode (search: exact) against the Embree reference, and the live error view: zero
// (an infinite PSNR, no pixel off by more than 32 levels) when the mode is exact itself.
#include <gtest/gtest.h>

#include <cstdio>

#include "../gl/gl_fixture.h"
#include "app/headless_frames.h"
#include "bench/accuracy.h"
#include "platform/native/model_paths.h"

namespace reflect {
namespace {

constexpr int kSize = 256;

AccuracySettings exactMode() {
  AccuracySettings a;
  a.search = Search::Exact;
  return a;
}

Scene shippedScene(const std::string& name) {
  auto scene = loadNamedScene(name);
  EXPECT_TRUE(scene) << scene.error();
  return scene ? scene.take() : Scene{};
}

TEST(ExactMode, MatchesTheReferenceOnTheMirror) {
  for (double t : {1.5, 5.0}) {
    auto demo = testing::makeDemo(makeDynamicReflectionScene());
    ASSERT_EQ(demo->setAccuracySettings(exactMode()), "");
    auto report = measureAccuracy(*demo, t, kSize, kSize);
    ASSERT_TRUE(report) << report.error();
    std::printf("t=%.1f: exact mode's reflector PSNR %.2f dB against Embree, max %d\n", t,
                report.value().reflector.psnrDb, report.value().reflector.maxPixelError);
    EXPECT_GT(report.value().reflector.psnrDb, 60.0);
    EXPECT_LT(report.value().meanAngularErrorDeg, 0.01);
  }
}

TEST(ExactMode, GlassAndTwoMirrorsMatchTheReference) {
  for (const char* name : {"glass-sphere", "two-mirrors"}) {
    auto demo = testing::makeDemo(shippedScene(name));
    ASSERT_EQ(demo->setAccuracySettings(exactMode()), "");
    auto report = measureAccuracy(*demo, 5.0, kSize, kSize);
    ASSERT_TRUE(report) << report.error();
    std::printf("%s: exact mode's reflector PSNR %.2f dB against Embree (max %d)\n", name,
                report.value().reflector.psnrDb, report.value().reflector.maxPixelError);
    // Two mirrors facing each other follow rays through up to four bounces, where a handful of
    // pixels at the other mirror's rim can go either way (47.8 dB at 256x256, 88.5 at 400x400).
    EXPECT_GT(report.value().reflector.psnrDb, 45.0) << name;
  }
}

const FrameStats& errorViewFrame(Demo& demo, double t) {
  EXPECT_EQ(demo.setShowError(true), "");
  auto image = renderFrameAt(demo, t, kSize, kSize);
  EXPECT_TRUE(image) << image.error();
  return demo.lastStats();
}

TEST(ErrorView, ZeroWhenTheModeIsExact) {
  for (const char* name : {"ex12-2", "glass-sphere", "skybox"}) {
    auto demo = testing::makeDemo(shippedScene(name));
    ASSERT_EQ(demo->setAccuracySettings(exactMode()), "");
    const FrameStats& s = errorViewFrame(*demo, 2.0);
    ASSERT_TRUE(s.errorView) << name;
    EXPECT_GT(s.errorReflectorPixels, 1000u) << name;
    EXPECT_EQ(s.errorRmse, 0.0) << name;
    EXPECT_EQ(s.errorPsnrDb, kPsnrCapDb) << name;
    EXPECT_EQ(s.errorPixelsOver32, 0u) << name;
  }
}

TEST(ErrorView, ShowsTheCubeMapsError) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  AccuracySettings plain;
  plain.search = Search::Plain;
  ASSERT_EQ(demo->setAccuracySettings(plain), "");
  const FrameStats& s = errorViewFrame(*demo, 2.0);
  ASSERT_TRUE(s.errorView);
  std::printf("plain lookup: %.2f dB, %zu of %zu pixels off by more than 32\n", s.errorPsnrDb,
              s.errorPixelsOver32, s.errorReflectorPixels);
  EXPECT_GT(s.errorRmse, 0.0);
  EXPECT_LT(s.errorPsnrDb, 45.0);
  EXPECT_GT(s.errorPixelsOver32, 0u);
  // Off: the stats carry no error view.
  ASSERT_EQ(demo->setShowError(false), "");
  auto image = renderFrameAt(*demo, 2.0, kSize, kSize);
  ASSERT_TRUE(image);
  EXPECT_FALSE(demo->lastStats().errorView);
}

}  // namespace
}  // namespace reflect
