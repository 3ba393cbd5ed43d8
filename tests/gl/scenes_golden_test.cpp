// Every shipped scene (assets/scenes/*.json) rendered headless at a fixed time against its golden
// PNG, with the same thresholds as the default scene's test (see golden_compare.h).
#include <gtest/gtest.h>

#include "app/headless_frames.h"
#include "gl_fixture.h"
#include "golden_compare.h"
#include "platform/native/model_paths.h"

namespace reflect {
namespace {

class ShippedScene : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedScene, MatchesGoldenAtTwoSeconds) {
  Result<Scene> scene = loadNamedScene(GetParam());
  ASSERT_TRUE(scene) << scene.error();
  const Scene shipped = scene.take();
  auto demo = testing::makeDemo(shipped);
  auto image = renderFrameAt(*demo, 2.0, 320, 240);
  ASSERT_TRUE(image) << image.error();
  // Scenes with mirrors or glass are held inside them too (ex12-1's cube is neither).
  testing::expectMatchesGolden(image.value(), "scene_" + GetParam() + ".png",
                               testing::reflectorMask(shipped, 2.0, 320, 240));
}

INSTANTIATE_TEST_SUITE_P(AllScenes, ShippedScene, ::testing::ValuesIn(shippedSceneNames()),
                         [](const auto& param) {
                           std::string name = param.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace reflect
