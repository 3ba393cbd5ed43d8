// Rough mirrors and frosted glass that read the static skybox (environment: skybox): the planner
// keeps the sky's prefiltered levels for them and filters the sky once, when those levels (or the
// sky) change; nothing of the sky is filtered where no skybox reader is rough.
#include <gtest/gtest.h>

#include "core/frame_planner.h"
#include "core/ggx.h"
#include "core/planner_parts.h"
#include "planned_boxes.h"

namespace reflect {
namespace {

using testing::boxAt;
using testing::mirrorAt;

constexpr int kSkyFaceSize = 256;

CaptureContext withSky(int roughLevels = 5, int skyFaceSize = kSkyFaceSize) {
  CaptureContext c;
  c.accuracy.search = Search::Hierarchical;
  c.accuracy.roughLevels = roughLevels;
  c.skyboxContent = 42;
  c.skyFaceSize = skyFaceSize;
  return c;
}

// A mirror (or glass) that looks the static skybox up: no live probe of its own.
PlannedObject skyReaderAt(glm::vec3 position, float roughness,
                          Material material = Material::Mirror) {
  PlannedObject o = mirrorAt(position, roughness);
  o.probed = false;
  o.look.environment = Environment::Skybox;
  o.look.material = material;
  o.look.ior = 1.5f;
  return o;
}

TEST(RoughSkyPlanning, NoSkyLevelsWhereNoSkyboxReaderIsRough) {
  FramePlanner planner;
  // A rough live mirror has levels of its own probe, not of the sky; the sharp sky readers none.
  const std::vector<PlannedObject> scene{skyReaderAt({0, 0, 0}, 0.0f),
                                         skyReaderAt({2, 0, 0}, 0.0f, Material::Glass),
                                         mirrorAt({4, 0, 0}, 0.5f), boxAt({0, 0, 5})};
  for (int frame = 0; frame < 2; ++frame) {
    const FramePlan plan = planner.plan(scene, withSky(), {});
    EXPECT_TRUE(plan.skyRoughLevels.empty());
    EXPECT_FALSE(plan.filterSky);
    EXPECT_EQ(plan.skyFilterSamples, 0.0);
    ASSERT_EQ(plan.probes.size(), 1u);
    // Its lobe taps read its capture (the default): no levels; the sky keeps its levels' rule.
    EXPECT_TRUE(plan.probes[0].roughLevels.empty());
    EXPECT_TRUE(plan.probes[0].lobeTapReaders);
  }
}

TEST(RoughSkyPlanning, NoSkyLevelsWithoutASkybox) {
  FramePlanner planner;
  const FramePlan plan = planner.plan({skyReaderAt({0, 0, 0}, 0.5f)}, withSky(5, 0), {});
  EXPECT_TRUE(plan.skyRoughLevels.empty());
  EXPECT_FALSE(plan.filterSky);
}

// A mirror of 0.5 reads levels 2 and 3 (2.5 of 5); frosted glass of 0.8 and index 1.5 its
// reflection's level 4 and the light through's levels 1 and 2 (transmissionRoughness 0.3 x 5).
// Each level once, ascending; on a sky of 16 texels a face only log2(16) = 4 levels fit, so 0.5
// reads level 2 alone.
TEST(RoughSkyPlanning, TheLevelsOfTheRoughSkyboxReaders) {
  FramePlanner planner;
  const std::vector<PlannedObject> scene{skyReaderAt({0, 0, 0}, 0.5f),
                                         skyReaderAt({2, 0, 0}, 0.8f, Material::Glass)};
  const FramePlan plan = planner.plan(scene, withSky(), {});
  EXPECT_EQ(plan.skyRoughLevels, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_TRUE(plan.probes.empty());
  FramePlanner small;
  EXPECT_EQ(small.plan({skyReaderAt({0, 0, 0}, 0.5f)}, withSky(5, 16), {}).skyRoughLevels,
            (std::vector<int>{2}));
}

// The sky is static: filtered on the first frame, with every texel of its levels times the
// samples, and not again while nothing changes, even as other objects move.
TEST(RoughSkyPlanning, TheSkyIsFilteredOnceWhileNothingChanges) {
  FramePlanner planner;
  std::vector<PlannedObject> scene{skyReaderAt({0, 0, 0}, 0.5f), boxAt({0, 0, 5})};
  const CaptureContext context = withSky();
  const FramePlan first = planner.plan(scene, context, {});
  EXPECT_TRUE(first.filterSky);
  // Levels 2 and 3 of a 256 sky: 6 x (64^2 + 32^2) texels x 32 samples.
  EXPECT_EQ(first.skyFilterSamples, 6.0 * (64 * 64 + 32 * 32) * 32);
  for (int frame = 1; frame < 4; ++frame) {
    scene[1].model = glm::translate(glm::mat4(1.0f), glm::vec3(frame, 0, 5));
    const FramePlan plan = planner.plan(scene, context, {});
    EXPECT_EQ(plan.skyRoughLevels, (std::vector<int>{2, 3}));
    EXPECT_FALSE(plan.filterSky) << "frame " << frame;
    EXPECT_EQ(plan.skyFilterSamples, 0.0);
  }
}

// Its levels change with a reader's roughness (0.5 -> 0.7: levels 3 and 4): filtered again, once.
// A new skybox is filtered again too; a planner that forgot everything (a lost context) as well.
TEST(RoughSkyPlanning, FilteredAgainWhenTheRoughnessOrTheSkyChanges) {
  FramePlanner planner;
  std::vector<PlannedObject> scene{skyReaderAt({0, 0, 0}, 0.5f)};
  CaptureContext context = withSky();
  EXPECT_TRUE(planner.plan(scene, context, {}).filterSky);
  EXPECT_FALSE(planner.plan(scene, context, {}).filterSky);
  scene[0].look.roughness = 0.7f;
  const FramePlan rougher = planner.plan(scene, context, {});
  EXPECT_EQ(rougher.skyRoughLevels, (std::vector<int>{3, 4}));
  EXPECT_TRUE(rougher.filterSky);
  EXPECT_FALSE(planner.plan(scene, context, {}).filterSky);
  context.skyboxContent = 43;
  EXPECT_TRUE(planner.plan(scene, context, {}).filterSky);
  EXPECT_FALSE(planner.plan(scene, context, {}).filterSky);
  planner.invalidate();
  EXPECT_TRUE(planner.plan(scene, context, {}).filterSky);
  // No longer rough: no levels, nothing filtered.
  scene[0].look.roughness = 0.0f;
  const FramePlan sharp = planner.plan(scene, context, {});
  EXPECT_TRUE(sharp.skyRoughLevels.empty());
  EXPECT_FALSE(sharp.filterSky);
}

// Search: exact traces the skybox readers' lobes: the sky keeps no levels for them.
TEST(RoughSkyPlanning, TracedSkyboxReadersNeedNoSkyLevels) {
  FramePlanner planner;
  CaptureContext context = withSky();
  context.accuracy.search = Search::Exact;
  const FramePlan plan = planner.plan({skyReaderAt({0, 0, 0}, 0.5f)}, context, {});
  EXPECT_TRUE(plan.traces(0));
  EXPECT_TRUE(plan.skyRoughLevels.empty());
  EXPECT_FALSE(plan.filterSky);
}

// FramePlanner::layout (a pass that reads what a plan captured) knows the sky's levels but
// filters nothing.
TEST(RoughSkyPlanning, TheLayoutKnowsTheSkyLevelsAndFiltersNothing) {
  const FramePlan plan = FramePlanner::layout({skyReaderAt({0, 0, 0}, 0.5f)}, withSky());
  EXPECT_EQ(plan.skyRoughLevels, (std::vector<int>{2, 3}));
  EXPECT_FALSE(plan.filterSky);
  EXPECT_EQ(plan.skyFilterSamples, 0.0);
}

}  // namespace
}  // namespace reflect
