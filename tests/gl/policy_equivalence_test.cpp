// When-changed capture (the default policy) redraws only the faces whose view changed: its frames
// must be the course's every-frame capture's, pixel for pixel, over a moving sequence. Held for
// the two ways a probe is looked up, the cube-map search (hierarchical) and the course's plain
// lookup (the `course` preset's accuracy: captured at the origin, 16-bit depth, one glass
// surface), on scenes with a mirror, glass and mirrors that see each other. Not under the default
// (search: planned), which traces every reflector of these scenes: both frames would capture
// nothing, and compare the same traced pictures. Every case proves it captured faces under both
// policies, and that when-changed redrew fewer.
#include <gtest/gtest.h>

#include <cstdio>

#include "app/headless_frames.h"
#include "core/presets.h"
#include "gfx/offscreen_target.h"
#include "gl_fixture.h"
#include "platform/native/model_paths.h"

namespace reflect {
namespace {

constexpr int kSize = 96;

std::unique_ptr<Demo> demoWith(const std::string& sceneName, const AccuracySettings& accuracy,
                               UpdatePolicy policy) {
  Result<Scene> scene = loadNamedScene(sceneName);
  EXPECT_TRUE(scene) << scene.error();
  auto demo = testing::makeDemo(scene ? scene.take() : Scene{});
  EXPECT_EQ(demo->setAccuracySettings(accuracy), "");
  PlannerSettings planner = demo->plannerSettings();
  planner.policy = policy;
  demo->setPlannerSettings(planner);
  return demo;
}

void expectSamePictures(const std::string& sceneName, const AccuracySettings& accuracy) {
  auto everyFrame = demoWith(sceneName, accuracy, UpdatePolicy::EveryFrame);
  auto whenChanged = demoWith(sceneName, accuracy, UpdatePolicy::WhenChanged);
  auto target = OffscreenTarget::create(kSize, kSize);
  ASSERT_TRUE(target);
  const std::string label = sceneName + " (" + accuracy.describe() + ")";
  int everyFrameFaces = 0, whenChangedFaces = 0;
  for (int frame = 0; frame < 12; ++frame) {
    // Steps of 0.1 s, with a pause of two frames in the middle (nothing moves: nothing redrawn).
    const double dt = frame == 0 || frame == 5 || frame == 6 ? 0.0 : 0.1;
    std::vector<RgbaImage> pictures;
    for (Demo* demo : {everyFrame.get(), whenChanged.get()}) {
      demo->frame(dt, target.value().framebuffer(), kSize, kSize, true);
      pictures.push_back(target.value().readPixels());
    }
    everyFrameFaces += everyFrame->lastStats().facesCaptured;
    whenChangedFaces += whenChanged->lastStats().facesCaptured;
    auto d = compareImages(pictures[0], pictures[1], 0);
    ASSERT_TRUE(d) << d.error();
    EXPECT_EQ(d.value().maxChannel, 0) << label << ", frame " << frame << ": "
                                       << d.value().fractionOver * 100 << "% of the pixels differ";
  }
  std::printf("%s: %d faces captured every frame, %d when changed\n", label.c_str(),
              everyFrameFaces, whenChangedFaces);
  // Not vacuous: both drew their reflections from captured faces, and when-changed redrew less.
  EXPECT_GT(everyFrameFaces, 0) << label;
  EXPECT_GT(whenChangedFaces, 0) << label;
  EXPECT_LT(whenChangedFaces, everyFrameFaces) << label;
}

TEST(PolicyEquivalence, WhenChangedDrawsWhatEveryFrameDraws) {
  AccuracySettings hierarchical;
  hierarchical.search = Search::Hierarchical;
  const AccuracySettings course = findPreset("course")->accuracy;
  for (const char* scene : {"ex12-2", "glass-sphere", "two-mirrors", "shared-probe"}) {
    for (const AccuracySettings& accuracy : {hierarchical, course}) {
      expectSamePictures(scene, accuracy);
    }
  }
}

}  // namespace
}  // namespace reflect
