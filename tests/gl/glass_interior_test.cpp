// The glass interior maps (gfx/glass_interior_map): made once per non-sphere glass mesh and only
// when a scene needs one, freed with the renderer, and made again after a lost context.
#include <gtest/gtest.h>

#include "app/headless_frames.h"
#include "gfx/gl_handle.h"
#include "gfx/scene_renderer.h"
#include "gl_fixture.h"
#include "platform/native/model_paths.h"

namespace reflect {
namespace {

constexpr int kSize = 96;

std::unique_ptr<Demo> demoOf(const std::string& nameOrPath, int glassSurfaces = 2) {
  Result<Scene> scene = loadNamedScene(nameOrPath);
  EXPECT_TRUE(scene) << scene.error();
  auto demo = testing::makeDemo(scene ? scene.take() : Scene{});
  AccuracySettings settings;
  settings.search = Search::Hierarchical;  // the interior map serves the captured probe
  settings.glassSurfaces = glassSurfaces;
  EXPECT_EQ(demo->setAccuracySettings(settings), "");
  return demo;
}

const std::string kGlassCube = std::string(TEST_DATA_DIR) + "/glass-cube.json";

TEST(GlassInterior, OnlyANonSphereGlassMeshWithTwoSurfacesGetsAMap) {
  auto sphere = demoOf("glass-sphere");
  ASSERT_TRUE(renderFrameAt(*sphere, 1.0, kSize, kSize));
  EXPECT_EQ(sphere->renderer()->glassInteriorMaps(), 0u);  // the closed form
  auto mirror = demoOf("ex12-2");
  ASSERT_TRUE(renderFrameAt(*mirror, 1.0, kSize, kSize));
  EXPECT_EQ(mirror->renderer()->glassInteriorMaps(), 0u);  // no glass at all
  auto oneSurface = demoOf(kGlassCube, 1);
  ASSERT_TRUE(renderFrameAt(*oneSurface, 1.0, kSize, kSize));
  EXPECT_EQ(oneSurface->renderer()->glassInteriorMaps(), 0u);
  auto cube = demoOf(kGlassCube);
  ASSERT_TRUE(renderFrameAt(*cube, 1.0, kSize, kSize));
  EXPECT_EQ(cube->renderer()->glassInteriorMaps(), 1u);
}

TEST(GlassInterior, MadeOnceFreedWithTheRendererAndRemadeAfterALostContext) {
  const long before = gLiveGlObjects;
  auto demo = demoOf(kGlassCube);
  Result<RgbaImage> first = renderFrameAt(*demo, 2.0, kSize, kSize);
  ASSERT_TRUE(first) << first.error();
  const long afterFirst = gLiveGlObjects;
  // The object is rigid: later frames (it spins) draw no new map.
  for (double t : {2.5, 3.0, 2.0}) ASSERT_TRUE(renderFrameAt(*demo, t, kSize, kSize));
  EXPECT_EQ(gLiveGlObjects, afterFirst);
  EXPECT_EQ(demo->renderer()->glassInteriorMaps(), 1u);

  // A lost context: the names are forgotten, then everything is made again from the CPU side,
  // the map included, and the frame is the same.
  demo->loseGraphics();
  ASSERT_EQ(demo->initGraphics(), "");
  Result<RgbaImage> restored = renderFrameAt(*demo, 2.0, kSize, kSize);
  ASSERT_TRUE(restored) << restored.error();
  EXPECT_EQ(demo->renderer()->glassInteriorMaps(), 1u);
  EXPECT_EQ(restored.value().pixels, first.value().pixels);

  // Released with the context alive: every GL object the demo made is deleted.
  demo->releaseGraphics();
  demo.reset();
  EXPECT_EQ(gLiveGlObjects, before);
}

}  // namespace
}  // namespace reflect
