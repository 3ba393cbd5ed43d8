// Rough mirrors that read the static skybox, in real frames: the sky's prefiltered cube is made
// and filtered on the first frame, not again while nothing it depends on changes (the figures
// moving and the live mirror recapturing do not count), again when the reader's roughness changes,
// and freed when no skybox reader is rough.
#include <gtest/gtest.h>

#include "app/headless_frames.h"
#include "core/ggx.h"
#include "gl_fixture.h"
#include "platform/native/model_paths.h"

namespace reflect {
namespace {

constexpr int kSkyMirror = 2;  // assets/scenes/skybox.json: the mirror that reads the sky

Scene skyboxScene(float mirrorRoughness) {
  Result<Scene> scene = loadNamedScene("skybox");
  EXPECT_TRUE(scene) << scene.error();
  Scene s = scene ? scene.take() : Scene{};
  if (s.objects.size() > kSkyMirror) s.objects[kSkyMirror].roughness = mirrorRoughness;
  return s;
}

// The samples the filter takes for `levels` of a sky of faceSize: every texel of six faces times
// the lobe samples the filter keeps (those above the surface).
double skySamples(const std::vector<int>& levels, int faceSize, int roughLevels) {
  double samples = 0.0;
  for (int level : levels) {
    const double side = std::max(faceSize >> level, 1);
    const float alpha = ggxAlpha(roughnessOfLevel(level, roughLevels));
    samples += 6.0 * side * side * static_cast<double>(prefilterLobe(alpha, 32, faceSize).size());
  }
  return samples;
}

void renderAt(Demo& demo, double seconds) {
  auto image = renderFrameAt(demo, seconds, 160, 120);
  ASSERT_TRUE(image) << image.error();
}

TEST(RoughSkyFrames, TheSkyIsFilteredOnceThenOnlyWhenItsLevelsChange) {
  auto demo = testing::makeCapturingDemo(skyboxScene(0.5f));
  ASSERT_NE(demo->skyboxFaces(), nullptr);
  const int faceSize = (*demo->skyboxFaces())[0].width;
  const int levels = usableRoughLevels(demo->accuracySettings().roughLevels, faceSize);
  ASSERT_EQ(levels, 5);
  renderAt(*demo, 2.0);
  // 0.5 x 5 = level 2.5: levels 2 and 3; the scene's live mirror is perfect: nothing else.
  EXPECT_EQ(demo->lastPlan().skyRoughLevels, (std::vector<int>{2, 3}));
  EXPECT_TRUE(demo->lastPlan().filterSky);
  EXPECT_GT(demo->lastStats().filterSamples, 0.0);
  EXPECT_EQ(demo->lastStats().filterSamples, skySamples({2, 3}, faceSize, levels));
  const GLuint filtered = demo->renderer()->skyPrefilteredTexture();
  EXPECT_NE(filtered, 0u);
  EXPECT_EQ(demo->renderer()->prefilteredCubes(), 0u);  // no live probe is rough

  for (double seconds : {2.5, 3.0}) {  // the figure orbits, the live mirror recaptures
    renderAt(*demo, seconds);
    EXPECT_FALSE(demo->lastPlan().filterSky);
    EXPECT_EQ(demo->lastStats().filterSamples, 0.0) << "t = " << seconds;
    EXPECT_EQ(demo->renderer()->skyPrefilteredTexture(), filtered);
  }

  ASSERT_EQ(demo->setMaterialJson(kSkyMirror, R"({"type": "mirror", "environment": "skybox",
      "reflection": 0.9, "base": 0.1, "roughness": 0.7})"),
            "");
  renderAt(*demo, 3.0);
  EXPECT_EQ(demo->lastPlan().skyRoughLevels, (std::vector<int>{3, 4}));
  EXPECT_EQ(demo->lastStats().filterSamples, skySamples({3, 4}, faceSize, levels));
  renderAt(*demo, 3.5);
  EXPECT_EQ(demo->lastStats().filterSamples, 0.0);

  ASSERT_EQ(demo->setMaterialJson(kSkyMirror, R"({"type": "mirror", "environment": "skybox",
      "reflection": 0.9, "base": 0.1, "roughness": 0})"),
            "");
  renderAt(*demo, 4.0);
  EXPECT_TRUE(demo->lastPlan().skyRoughLevels.empty());
  EXPECT_EQ(demo->lastStats().filterSamples, 0.0);
  EXPECT_EQ(demo->renderer()->skyPrefilteredTexture(), 0u);  // freed: no rough reader
}

// A sky without rough readers (the shipped scene, every roughness 0) is never filtered.
TEST(RoughSkyFrames, ASharpSkyIsNeverFiltered) {
  auto demo = testing::makeCapturingDemo(skyboxScene(0.0f));
  for (double seconds : {0.0, 0.5}) {
    renderAt(*demo, seconds);
    EXPECT_EQ(demo->lastStats().filterSamples, 0.0);
    EXPECT_EQ(demo->renderer()->skyPrefilteredTexture(), 0u);
  }
}

}  // namespace
}  // namespace reflect
