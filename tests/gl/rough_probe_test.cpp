// Rough mirrors' probes in a real frame: a scene of perfect mirrors makes no filtered cube, takes
// no filter sample and keeps no box chain (its frame is today's); under the default each rough
// sphere's probe keeps the box chain its lobe taps read and nothing is prefiltered; with lobe
// taps off each gets a prefiltered cube, and the filter's work is what the planner counted.
#include <gtest/gtest.h>

#include "app/headless_frames.h"
#include "core/ggx.h"
#include "gl_fixture.h"
#include "platform/native/model_paths.h"

namespace reflect {
namespace {

Scene roughSpheres(bool keepRoughness) {
  Result<Scene> scene = loadNamedScene("rough-spheres");
  EXPECT_TRUE(scene) << scene.error();
  Scene s = scene.take();
  if (!keepRoughness) {
    for (SceneObject& o : s.objects) o.roughness = 0.0f;
  }
  return s;
}

TEST(RoughProbe, PerfectMirrorsAreNeverFiltered) {
  auto demo = testing::makeCapturingDemo(roughSpheres(false));
  for (int frame = 0; frame < 3; ++frame) {
    auto image = renderFrameAt(*demo, 0.5 * frame, 160, 120);
    ASSERT_TRUE(image) << image.error();
    EXPECT_EQ(demo->lastStats().filterSamples, 0.0);
    for (const ProbePlan& probe : demo->lastPlan().probes) {
      EXPECT_FALSE(probe.lobeTapReaders);
      const CubeCaptureTarget* t = demo->renderer()->probeTarget(probe.reflector);
      ASSERT_NE(t, nullptr);
      EXPECT_FALSE(t->format().boxChain);
    }
  }
  EXPECT_EQ(demo->renderer()->prefilteredCubes(), 0u);
}

TEST(RoughProbe, LobeTapReadersKeepABoxChainAndNoFilteredCube) {
  auto demo = testing::makeCapturingDemo(roughSpheres(true));
  auto image = renderFrameAt(*demo, 2.0, 160, 120);
  ASSERT_TRUE(image) << image.error();
  EXPECT_EQ(demo->renderer()->prefilteredCubes(), 0u);
  EXPECT_EQ(demo->lastStats().filterSamples, 0.0);
  // Five spheres with a probe each, four of them rough (0.25, 0.5, 0.75, 1): those four keep a
  // box chain; the perfect one does not.
  int tapped = 0, chained = 0;
  for (const ProbePlan& probe : demo->lastPlan().probes) {
    EXPECT_TRUE(probe.roughLevels.empty());
    const CubeCaptureTarget* t = demo->renderer()->probeTarget(probe.reflector);
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->format().boxChain, probe.lobeTapReaders);
    tapped += probe.lobeTapReaders ? 1 : 0;
    chained += t->format().boxChain ? 1 : 0;
  }
  EXPECT_EQ(tapped, 4);
  EXPECT_EQ(chained, 4);
}

TEST(RoughProbe, EachRoughProbeIsFilteredAtTheLevelsItNeeds) {
  auto demo = testing::makeCapturingDemo(roughSpheres(true));
  AccuracySettings prefiltered = demo->accuracySettings();
  prefiltered.lobeTaps = 0;
  ASSERT_EQ(demo->setAccuracySettings(prefiltered), "");
  auto image = renderFrameAt(*demo, 2.0, 160, 120);
  ASSERT_TRUE(image) << image.error();
  // Four rough spheres (0.25, 0.5, 0.75, 1), each with a probe of its own; the first is perfect.
  EXPECT_EQ(demo->renderer()->prefilteredCubes(), 4u);
  // Rough levels of 5 at 32 samples a texel on 128-texel faces: 0.25 -> {1, 2}, 0.5 -> {2, 3},
  // 0.75 -> {3, 4}, 1 -> {5}; each sample the lobe keeps (those above the surface).
  const int size = 128;
  double expected = 0.0;
  for (const std::vector<int>& levels : {std::vector<int>{1, 2}, std::vector<int>{2, 3},
                                         std::vector<int>{3, 4}, std::vector<int>{5}}) {
    for (int level : levels) {
      const double texels = 6.0 * (size >> level) * (size >> level);
      expected +=
          texels * static_cast<double>(prefilterLobe(ggxAlpha(level / 5.0f), 32, size).size());
    }
  }
  EXPECT_EQ(demo->lastStats().filterSamples, expected);
}

}  // namespace
}  // namespace reflect
