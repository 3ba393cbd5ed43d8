// Rough mirrors and frosted glass in the frame planner: which prefiltered levels a probe keeps,
// when they are filtered, and what the method costs count for them. Nothing is filtered where
// nothing is rough.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/frame_planner.h"
#include "core/ggx.h"
#include "core/planner_parts.h"
#include "planned_boxes.h"

namespace reflect {
namespace {

using testing::boxAt;
using testing::mirrorAt;

// The prefiltered levels' planning (lobe taps off), unless `lobeTaps` is given.
CaptureContext capturing(int roughLevels = 5, int lobeTaps = 0) {
  CaptureContext c;
  c.accuracy.search = Search::Hierarchical;
  c.accuracy.roughLevels = roughLevels;
  c.accuracy.lobeTaps = lobeTaps;
  return c;
}

TEST(RoughLevels, TheTwoLevelsAroundEachRoughness) {
  EXPECT_EQ(roughLevelsFor(0.0f, 5).lower, 0);
  EXPECT_EQ(roughLevelsFor(0.0f, 5).upper, 0);
  EXPECT_EQ(roughLevelsFor(0.25f, 5).lower, 1);  // 1.25
  EXPECT_EQ(roughLevelsFor(0.25f, 5).upper, 2);
  EXPECT_EQ(roughLevelsFor(0.1f, 5).lower, 0);  // 0.5: the capture and level 1
  EXPECT_EQ(roughLevelsFor(0.1f, 5).upper, 1);
  EXPECT_EQ(roughLevelsFor(0.4f, 5).lower, 2);  // exactly level 2
  EXPECT_EQ(roughLevelsFor(0.4f, 5).upper, 2);
  EXPECT_EQ(roughLevelsFor(1.0f, 5).upper, 5);
  EXPECT_EQ(roughLevelsFor(3.0f, 5).upper, 5);  // past 1: held at 1
  EXPECT_FLOAT_EQ(roughnessOfLevel(2, 5), 0.4f);
}

TEST(RoughPlanning, NothingIsFilteredWhereNothingIsRough) {
  FramePlanner planner;
  const std::vector<PlannedObject> scene{mirrorAt({0, 0, 0}, 0.0f), mirrorAt({4, 0, 0}, 0.0f),
                                         boxAt({0, 0, 5})};
  for (int frame = 0; frame < 3; ++frame) {
    const FramePlan plan = planner.plan(scene, capturing(), {});
    ASSERT_EQ(plan.probes.size(), 2u);
    for (const ProbePlan& probe : plan.probes) {
      EXPECT_TRUE(probe.roughLevels.empty());
      EXPECT_EQ(probe.filterFaces, 0u);
    }
  }
}

TEST(RoughPlanning, LobeTapReadersKeepNoLevelsAndAreNeverFiltered) {
  FramePlanner planner;
  const std::vector<PlannedObject> scene{mirrorAt({0, 0, 0}, 0.0f), mirrorAt({4, 0, 0}, 0.5f),
                                         mirrorAt({8, 0, 0}, 1.0f)};
  for (int frame = 0; frame < 2; ++frame) {
    const FramePlan plan = planner.plan(scene, capturing(5, 16), {});
    ASSERT_EQ(plan.probes.size(), 3u);
    EXPECT_FALSE(plan.probes[0].lobeTapReaders);
    EXPECT_TRUE(plan.probes[1].lobeTapReaders);
    EXPECT_TRUE(plan.probes[2].lobeTapReaders);
    for (const ProbePlan& probe : plan.probes) {
      EXPECT_TRUE(probe.roughLevels.empty());
      EXPECT_EQ(probe.filterFaces, 0u);
    }
  }
}

// A probe read only by rough mirrors' lobe taps is captured at the size their lobes need: the
// scene's halved while a tap at its lobe's peak covers 4 texels across (N alpha sqrt(6 / taps)),
// never under 32. Narrow lobes, more taps, glass and a perfect mirror keep more or the scene's.
TEST(RoughPlanning, ALobeTapProbeIsCapturedAtTheSizeItsLobesNeed) {
  const std::vector<PlannedObject> scene{mirrorAt({0, 0, 0}, 0.5f), mirrorAt({4, 0, 0}, 1.0f),
                                         mirrorAt({8, 0, 0}, 0.25f), mirrorAt({12, 0, 0}, 0.0f),
                                         mirrorAt({16, 0, 0}, 0.5f)};
  std::vector<PlannedObject> withGlass = scene;
  withGlass[4].look.material = Material::Glass;
  const auto sizes = [](const std::vector<PlannedObject>& objects, int faceSize, int taps) {
    CaptureContext context = capturing(5, taps);
    context.faceSize = faceSize;
    FramePlanner planner;
    std::vector<int> probeSizes;
    for (const ProbePlan& probe : planner.plan(objects, context, {}).probes) {
      probeSizes.push_back(probe.faceSize);
    }
    return probeSizes;
  };
  // 0.5 at 128: 0.25 x 0.61 = 0.153 texels a face texel, 4.9 at 32; 0.25: 2.45 at 64, so 128.
  EXPECT_EQ(sizes(scene, 128, 16), (std::vector<int>{32, 32, 0, 0, 32}));
  EXPECT_EQ(sizes(withGlass, 128, 16), (std::vector<int>{32, 32, 0, 0, 0}));
  EXPECT_EQ(sizes(scene, 512, 16), (std::vector<int>{32, 32, 128, 0, 32}));
  // 32 taps: each covers less of the lobe (0.5: 3.46 at 32, so 64).
  EXPECT_EQ(sizes(scene, 128, 32), (std::vector<int>{64, 32, 0, 0, 64}));
  // No lobe taps: the prefiltered levels are filtered from faces of the scene's size.
  EXPECT_EQ(sizes(scene, 128, 0), (std::vector<int>{0, 0, 0, 0, 0}));
  // The cost counts the probe's own texels.
  CaptureContext planned;
  planned.faceSize = 128;
  MethodCosts costs;
  costs.tracePixel = 1e6;
  costs.texel = 1.0;
  FramePlanner planner;
  planner.setCosts(costs);
  const PlannerView view{{0.0f, 0.0f, 20.0f}, 400.0f, 800.0f * 800.0f};
  PlannerSettings everyFrame;
  everyFrame.policy = UpdatePolicy::EveryFrame;
  planner.plan({scene[0]}, planned, everyFrame, view);
  ASSERT_EQ(planner.choices().size(), 1u);
  EXPECT_DOUBLE_EQ(planner.choices()[0].capture.texels, 6.0 * 32.0 * 32.0);  // one layer
}

// A probe whose face size changes forgets its faces: they are drawn again at the new size.
TEST(RoughPlanning, ANewFaceSizeRedrawsEveryFace) {
  std::vector<PlannedObject> scene{mirrorAt({0, 0, 0}, 1.0f), boxAt({0, 0, 5})};
  CaptureContext context = capturing(5, 16);
  context.faceSize = 128;
  PlannerSettings settings;
  settings.policy = UpdatePolicy::WhenChanged;
  FramePlanner planner;
  EXPECT_EQ(planner.plan(scene, context, settings).probes[0].faces.size(), 6u);
  EXPECT_EQ(planner.plan(scene, context, settings).probes[0].faces.size(), 0u);
  scene[0].look.roughness = 0.25f;  // a narrow lobe: the scene's 128 texels
  const FramePlan narrow = planner.plan(scene, context, settings);
  EXPECT_EQ(narrow.probes[0].faceSize, 0);
  EXPECT_EQ(narrow.probes[0].faces.size(), 6u);
}

TEST(RoughPlanning, EachProbeKeepsTheLevelsItsReadersNeed) {
  FramePlanner planner;
  const FramePlan plan = planner.plan(
      {mirrorAt({0, 0, 0}, 0.0f), mirrorAt({4, 0, 0}, 0.5f), mirrorAt({8, 0, 0}, 1.0f)},
      capturing(4), {});
  ASSERT_EQ(plan.probes.size(), 3u);
  EXPECT_TRUE(plan.probes[0].roughLevels.empty());
  EXPECT_EQ(plan.probes[1].roughLevels, (std::vector<int>{2}));  // 0.5 x 4 = level 2 exactly
  EXPECT_EQ(plan.probes[2].roughLevels, (std::vector<int>{4}));
  EXPECT_EQ(plan.probes[0].filterFaces, 0u);
  EXPECT_EQ(plan.probes[1].filterFaces, 0x3Fu);  // first frame: captured, so filtered
}

// Frosted glass reads two lobes: its reflection's (roughness 0.8 x 5 = level 4) and the light
// through it's, narrower (transmissionRoughness: 0.8 x 0.75 x sqrt(0.5 / 2) = 0.3, x 5 = 1.5:
// levels 1 and 2). Polished glass reads none.
TEST(RoughPlanning, FrostedGlassKeepsTheLevelsOfItsReflectionAndOfTheLightThrough) {
  PlannedObject frosted = mirrorAt({0, 0, 0}, 0.8f);
  frosted.look.material = Material::Glass;
  frosted.look.ior = 1.5f;
  PlannedObject polished = mirrorAt({4, 0, 0}, 0.0f);
  polished.look.material = Material::Glass;
  EXPECT_FLOAT_EQ(transmissionRoughness(0.8f, 1.5f), 0.3f);
  FramePlanner planner;
  const FramePlan plan = planner.plan({frosted, polished, boxAt({0, 0, 5})}, capturing(5), {});
  ASSERT_EQ(plan.probes.size(), 2u);
  EXPECT_EQ(plan.probes[0].roughLevels, (std::vector<int>{1, 2, 4}));
  EXPECT_EQ(plan.probes[0].filterFaces, 0x3Fu);
  EXPECT_TRUE(plan.probes[1].roughLevels.empty());
  EXPECT_EQ(plan.probes[1].filterFaces, 0u);
}

TEST(RoughPlanning, FiltersWhenAFaceIsRedrawnOrTheLevelsChange) {
  FramePlanner planner;
  PlannerSettings settings;
  settings.policy = UpdatePolicy::WhenChanged;
  std::vector<PlannedObject> scene{mirrorAt({0, 0, 0}, 0.3f), boxAt({0, 0, 5})};
  EXPECT_EQ(planner.plan(scene, capturing(), settings).probes[0].filterFaces, 0x3Fu);
  // Nothing moved: no face redrawn, nothing filtered.
  FramePlan still = planner.plan(scene, capturing(), settings);
  EXPECT_TRUE(still.probes[0].faces.empty());
  EXPECT_EQ(still.probes[0].filterFaces, 0u);
  EXPECT_EQ(still.probes[0].roughLevels, (std::vector<int>{1, 2}));  // 1.5: kept all the same
  // The box moves: its face is redrawn, and every face's levels with it (lobes cross edges).
  scene[1].model = glm::translate(glm::mat4(1.0f), {0, 0, 6});
  FramePlan moved = planner.plan(scene, capturing(), settings);
  EXPECT_EQ(moved.probes[0].faces.size(), 1u);
  EXPECT_EQ(moved.probes[0].filterFaces, 0x3Fu);
  // The mirror gets rougher: new levels, filtered though no face is redrawn.
  scene[0].look.roughness = 0.9f;
  FramePlan rougher = planner.plan(scene, capturing(), settings);
  EXPECT_TRUE(rougher.probes[0].faces.empty());
  EXPECT_EQ(rougher.probes[0].roughLevels, (std::vector<int>{4, 5}));
  EXPECT_EQ(rougher.probes[0].filterFaces, 0x3Fu);
}

TEST(RoughPlanning, ARoughPixelTracesLobeRaysAndAFilteredProbeCostsItsSamples) {
  MethodCosts costs;
  costs.tracePixel = 1.0;
  costs.filterSample = 0.5;
  TraceWork trace;
  trace.pixels = 100.0;
  trace.lobePixels = 40.0;
  trace.lobeRays = 16.0;
  EXPECT_DOUBLE_EQ(traceCost(trace, costs), 60.0 + 40.0 * 16.0);
  CaptureWork capture;
  capture.filterSamples = 8.0;
  EXPECT_DOUBLE_EQ(captureCost(capture, costs), 4.0);
  // Lobe taps are paid per rough pixel and tap.
  costs.lobeTap = 0.25;
  capture.lobeTaps = 40.0 * 16.0;
  EXPECT_DOUBLE_EQ(captureCost(capture, costs), 4.0 + 160.0);
  // Levels 1 and 2 of a 64-texel probe, all six faces, 32 samples a texel.
  EXPECT_DOUBLE_EQ(planner::filterSamplesFor({1, 2}, 64, 32), 6.0 * (32 * 32 + 16 * 16) * 32);
}

// Search: planned weighs a captured rough mirror with its lobe's quarters' searches, four a pixel
// (lobeQuarters), frosted glass with its light through's four, and the perfect mirror without;
// lobeQuarters off counts none.
TEST(RoughPlanning, ACapturedRoughReaderCostsItsQuartersSearches) {
  std::vector<PlannedObject> scene{mirrorAt({0, 0, 0}, 0.5f), mirrorAt({4, 0, 0}, 0.0f),
                                   mirrorAt({8, 0, 0}, 0.5f)};
  scene[2].look.material = Material::Glass;
  MethodCosts costs;  // tracing made dear: every probe is captured
  costs.tracePixel = 1e6;
  costs.lobeSearch = 0.5;
  const PlannerView view{{0.0f, 0.0f, 20.0f}, 400.0f, 800.0f * 800.0f};
  for (bool quarters : {true, false}) {
    CaptureContext planned;
    ASSERT_EQ(planned.accuracy.search, Search::Planned);
    ASSERT_EQ(planned.accuracy.lobeTaps, 16);
    planned.accuracy.lobeQuarters = quarters;
    FramePlanner planner;
    planner.setCosts(costs);
    const FramePlan plan = planner.plan(scene, planned, {}, view);
    ASSERT_EQ(planner.choices().size(), 3u);
    for (const MethodChoice& choice : planner.choices()) {
      const ProbePlan* probe = plan.probeOf(choice.reflector);
      ASSERT_NE(probe, nullptr);
      EXPECT_FALSE(plan.traces(choice.reflector));
      EXPECT_GT(choice.trace.pixels, 0.0);
      const bool rough = choice.reflector != 1;
      ASSERT_EQ(probe->plainLookupSuffices, false) << "reflector " << choice.reflector;
      const double searches = quarters && rough ? kLobeQuarters * choice.trace.pixels : 0.0;
      EXPECT_DOUBLE_EQ(choice.capture.lobeSearches, searches) << "reflector " << choice.reflector;
      CaptureWork without = choice.capture;
      without.lobeSearches = 0.0;
      EXPECT_DOUBLE_EQ(choice.captureMs, captureCost(without, costs) + 0.5 * searches);
    }
  }
}

// A lobe too narrow for the capture (roughness under 0.375) is traced under search: planned
// where the weighing chose the capture, with narrowLobeRays rays (narrow frosted glass with half
// as many for each of its two lobes); a wider one is weighed as before; narrowLobeRays 0
// captures it; a trace the weighing chose, and the exact mode, cast lobeRays.
TEST(RoughPlanning, ANarrowLobeIsTracedWithItsOwnRaysWhateverTheCost) {
  std::vector<PlannedObject> scene{mirrorAt({0, 0, 0}, 0.25f), mirrorAt({4, 0, 0}, 0.5f),
                                   mirrorAt({8, 0, 0}, 0.0f), mirrorAt({12, 0, 0}, 0.25f),
                                   mirrorAt({16, 0, 0}, 0.5f)};
  scene[3].look.material = Material::Glass;
  scene[4].look.material = Material::Glass;
  CaptureContext planned;
  ASSERT_EQ(planned.accuracy.search, Search::Planned);
  ASSERT_EQ(planned.accuracy.narrowLobeRays, 8);
  MethodCosts costs;  // tracing made dear: the other mirrors stay captured
  costs.tracePixel = 1e6;
  const PlannerView view{{0.0f, 0.0f, 20.0f}, 400.0f, 800.0f * 800.0f};
  FramePlanner planner;
  planner.setCosts(costs);
  const FramePlan plan = planner.plan(scene, planned, {}, view);
  EXPECT_TRUE(plan.traces(0));
  EXPECT_FALSE(plan.traces(1));
  EXPECT_FALSE(plan.traces(2));
  EXPECT_TRUE(plan.traces(3));
  EXPECT_FALSE(plan.traces(4));
  EXPECT_EQ(plan.lobeRays, (std::vector<int>{8, 0, 0, 4, 0}));
  EXPECT_EQ(plan.narrowTraced, (std::vector<int>{0, 3}));
  EXPECT_TRUE(tracedForNarrowLobe(scene[0].look, planned.accuracy));
  EXPECT_FALSE(tracedForNarrowLobe(scene[1].look, planned.accuracy));
  EXPECT_FALSE(tracedForNarrowLobe(scene[2].look, planned.accuracy));  // perfect: no lobe
  EXPECT_TRUE(tracedForNarrowLobe(scene[3].look, planned.accuracy));   // frosted glass, 0.25
  EXPECT_FALSE(tracedForNarrowLobe(scene[4].look, planned.accuracy));  // frosted glass, 0.5
  AccuracySettings one = planned.accuracy;
  one.narrowLobeRays = 1;  // glass still casts a ray for each lobe
  EXPECT_EQ(narrowLobeRaysOf(scene[0].look, one), 1);
  EXPECT_EQ(narrowLobeRaysOf(scene[3].look, one), 1);

  CaptureContext off = planned;
  off.accuracy.narrowLobeRays = 0;
  FramePlanner capturing;
  capturing.setCosts(costs);
  EXPECT_FALSE(capturing.plan(scene, off, {}, view).traces(0));

  // Where the weighing itself finds tracing cheaper, the lobe casts lobeRays, narrow or not, and
  // keeps them the next frame (the forced trace is not the weighing's memory).
  costs.tracePixel = 0.0;
  costs.face = 1.0;
  FramePlanner cheap;
  cheap.setCosts(costs);
  for (int frame = 0; frame < 2; ++frame) {
    const FramePlan p = cheap.plan(scene, planned, {}, view);
    EXPECT_TRUE(p.traces(0));
    EXPECT_TRUE(p.traces(1));
    EXPECT_TRUE(p.narrowTraced.empty());
    EXPECT_EQ(p.lobeRays, (std::vector<int>{16, 16, 0, 16, 16}));
  }

  CaptureContext exact = planned;
  exact.accuracy.search = Search::Exact;
  FramePlanner tracing;
  const FramePlan all = tracing.plan(scene, exact, {}, view);
  EXPECT_EQ(all.lobeRays, (std::vector<int>{16, 16, 0, 16, 16}));
}

TEST(PrefilterLobe, WeightsSumToOneAboveTheSurfaceAndWiderLobesReadCoarserLevels) {
  for (float alpha : {0.04f, 0.25f, 1.0f}) {
    const std::vector<glm::vec4> lobe = prefilterLobe(alpha, 32, 128);
    ASSERT_FALSE(lobe.empty());
    EXPECT_LE(lobe.size(), 32u);
    float total = 0.0f;
    for (const glm::vec4& s : lobe) {
      EXPECT_GT(s.z, 0.0f);  // above the surface (the normal is +z)
      EXPECT_GE(s.w, 0.0f);
      total += glm::length(glm::vec3(s));  // a sample's length is its weight
    }
    EXPECT_NEAR(total, 1.0f, 1e-5f);
  }
  // The lobe's centre sample (hammersley point 0: h = n) reads a level that grows with alpha.
  EXPECT_LT(prefilterLobe(0.04f, 32, 128)[0].w, prefilterLobe(1.0f, 32, 128)[0].w);
  // More samples, each a smaller share of the lobe: a finer level.
  EXPECT_GT(prefilterLobe(0.25f, 8, 128)[0].w, prefilterLobe(0.25f, 128, 128)[0].w);
  // Held to kMaxFilterSamples (less those below the surface).
  EXPECT_EQ(prefilterLobe(0.25f, 4096, 128).size(),
            prefilterLobe(0.25f, kMaxFilterSamples, 128).size());
}

}  // namespace
}  // namespace reflect
