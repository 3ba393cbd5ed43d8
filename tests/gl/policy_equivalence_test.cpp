// When-changed capture (the default policy) redraws only the faces whose view changed: its frames
// must be the course's every-frame capture's, pixel for pixel, over a moving sequence. Held for
// the cube-map path (the hierarchical search) and for the default (planned), on scenes with a
// mirror, glass and mirrors that see each other.
#include <gtest/gtest.h>

#include "app/headless_frames.h"
#include "gfx/offscreen_target.h"
#include "gl_fixture.h"
#include "platform/native/model_paths.h"

namespace reflect {
namespace {

constexpr int kSize = 96;

std::unique_ptr<Demo> demoWith(const std::string& sceneName, Search search, UpdatePolicy policy) {
  Result<Scene> scene = loadNamedScene(sceneName);
  EXPECT_TRUE(scene) << scene.error();
  auto demo = testing::makeDemo(scene ? scene.take() : Scene{});
  AccuracySettings accuracy;
  accuracy.search = search;
  EXPECT_EQ(demo->setAccuracySettings(accuracy), "");
  PlannerSettings planner = demo->plannerSettings();
  planner.policy = policy;
  demo->setPlannerSettings(planner);
  return demo;
}

void expectSamePictures(const std::string& sceneName, Search search) {
  auto everyFrame = demoWith(sceneName, search, UpdatePolicy::EveryFrame);
  auto whenChanged = demoWith(sceneName, search, UpdatePolicy::WhenChanged);
  auto target = OffscreenTarget::create(kSize, kSize);
  ASSERT_TRUE(target);
  int facesSaved = 0;
  for (int frame = 0; frame < 12; ++frame) {
    // Steps of 0.1 s, with a pause of two frames in the middle (nothing moves: nothing redrawn).
    const double dt = frame == 0 || frame == 5 || frame == 6 ? 0.0 : 0.1;
    std::vector<RgbaImage> pictures;
    for (Demo* demo : {everyFrame.get(), whenChanged.get()}) {
      demo->frame(dt, target.value().framebuffer(), kSize, kSize, true);
      pictures.push_back(target.value().readPixels());
    }
    facesSaved += everyFrame->lastStats().facesCaptured - whenChanged->lastStats().facesCaptured;
    auto d = compareImages(pictures[0], pictures[1], 0);
    ASSERT_TRUE(d) << d.error();
    EXPECT_EQ(d.value().maxChannel, 0)
        << sceneName << " (" << searchName(search) << "), frame " << frame << ": "
        << d.value().fractionOver * 100 << "% of the pixels differ";
  }
  if (search == Search::Hierarchical) {
    EXPECT_GT(facesSaved, 0) << "not vacuous: it redrew less";
  }
}

TEST(PolicyEquivalence, WhenChangedDrawsWhatEveryFrameDraws) {
  for (const char* scene : {"ex12-2", "glass-sphere", "two-mirrors", "shared-probe"}) {
    for (Search search : {Search::Hierarchical, Search::Planned}) {
      expectSamePictures(scene, search);
    }
  }
}

}  // namespace
}  // namespace reflect
