// The frame planner's levels of detail and chunks: coarser levels for objects small in a face or
// in the view, the second layer drawn coarser and only where something hides, and only the chunks
// a face can see.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include "core/frame_planner.h"
#include "core/frustum.h"
#include "planned_boxes.h"

namespace reflect {
namespace {

using testing::boxAt;
using testing::kNX;
using testing::kNZ;
using testing::kPX;
using testing::kPY;
using testing::kPZ;
using testing::mirrorAt;

TEST(FramePlanner, CoarserLevelsForObjectsSmallInTheFace) {
  FramePlanner planner;
  PlannerSettings lod;
  lod.captureLod = 0.5f;  // 256-pixel faces
  auto withLevels = [](PlannedObject o) {
    o.levels = {{4000, nullptr}, {1000, nullptr}, {250, nullptr}};
    return o;
  };
  // Bounding radius sqrt(3)/2. At 3 units: 37 px radius, 4280 px^2, wants 2140 triangles: level 0.
  // At 5 units: 22 px, wants 774: level 1. At 40 units: 2.8 px, wants 12: level 2 (the last).
  const FramePlan plan =
      planner.plan({mirrorAt({0, 0, 0}), withLevels(boxAt({3, 0, 0})),
                    withLevels(boxAt({0, 0, -5})), withLevels(boxAt({0, 0, 40}))},
                   {}, lod);
  auto drawOf = [&](int face, int object) {
    for (const FacePlan& f : plan.probes[0].faces)
      for (const DrawItem& d : f.draws)
        if (f.face == face && d.object == object) return d;
    return DrawItem{-1, -1, {}, 0};
  };
  EXPECT_EQ(drawOf(kPX, 1).lod, 0);
  EXPECT_EQ(drawOf(kPX, 1).triangles, 4000u);
  EXPECT_EQ(drawOf(kNZ, 2).lod, 1);
  EXPECT_EQ(drawOf(kPZ, 3).lod, 2);
  EXPECT_EQ(drawOf(kPZ, 3).triangles, 250u);
  // LOD off (captureLod 0, full detail as a setting): full detail everywhere.
  FramePlanner off;
  PlannerSettings lodOff;
  lodOff.captureLod = 0.0f;
  const FramePlan full = off.plan({mirrorAt({0, 0, 0}), withLevels(boxAt({0, 0, 40}))}, {}, lodOff);
  EXPECT_EQ(full.probes[0].faces[kPZ].draws.at(0).lod, 0);
  // On by default (the rule `reflect bench --lod-sweep` chose); view LOD off by default.
  FramePlanner byDefault;
  const FramePlan coarse =
      byDefault.plan({mirrorAt({0, 0, 0}), withLevels(boxAt({0, 0, 40}))}, {}, {});
  EXPECT_EQ(coarse.probes[0].faces[kPZ].draws.at(0).lod, 2);
  EXPECT_GT(PlannerSettings{}.captureLod, 0.0f);
  EXPECT_EQ(PlannerSettings{}.viewLod, 0.0f);
}

TEST(FramePlanner, TheSecondLayerDrawsCoarserAndOnlyWhereSomethingHides) {
  auto withLevels = [](PlannedObject o) {
    o.levels = {{4000, nullptr}, {1000, nullptr}, {250, nullptr}};
    return o;
  };
  // +X shows a box at 3 units (level 0 in the first layer: it wants 2140 triangles) in front of
  // another at 8; -Z shows one box alone.
  PlannedObject mirror = mirrorAt({0, 0, 0});
  mirror.look.material = Material::Mirror;  // it searches its surroundings
  const std::vector<PlannedObject> scene = {mirror, withLevels(boxAt({3, 0, 0})),
                                            withLevels(boxAt({8, 0, 0})),
                                            withLevels(boxAt({0, 0, -5}))};
  auto faceOf = [](const FramePlan& plan, int face) {
    for (const FacePlan& f : plan.probes[0].faces)
      if (f.face == face) return f;
    return FacePlan{};
  };
  for (UpdatePolicy policy : {UpdatePolicy::WhenChanged, UpdatePolicy::EveryFrame}) {
    FramePlanner planner;
    PlannerSettings settings;
    settings.policy = policy;
    const FramePlan plan = planner.plan(scene, {}, settings);
    ASSERT_EQ(plan.probes[0].layers, 2);
    const FacePlan px = faceOf(plan, kPX);
    EXPECT_EQ(px.layers, 2);
    // A sixteenth of the triangles per pixel: the near box wants 134, level 2.
    ASSERT_EQ(px.secondLayerDraws.size(), 2u);
    EXPECT_EQ(px.secondLayerDraws[0].object, 1);
    EXPECT_EQ(px.secondLayerDraws[0].lod, 2);
    // Beyond the course's capture, culled under every policy: -Z's box is not drawn in +X.
    for (const DrawItem& d : px.secondLayerDraws) EXPECT_NE(d.object, 3);
    const FacePlan nz = faceOf(plan, kNZ);
    if (policy == UpdatePolicy::WhenChanged) {
      EXPECT_EQ(nz.layers, 1);  // one object: nothing to hide
      EXPECT_TRUE(nz.secondLayerDraws.empty());
    }
  }
  // Capture LOD off (full detail as a setting): the second layer at full detail too.
  FramePlanner planner;
  PlannerSettings full;
  full.captureLod = 0.0f;
  const FramePlan plan = planner.plan(scene, {}, full);
  for (const DrawItem& d : faceOf(plan, kPX).secondLayerDraws) EXPECT_EQ(d.lod, 0);
}

TEST(FramePlanner, ViewLodPicksLevelsByTheObjectsSizeInTheView) {
  auto withLevels = [](PlannedObject o) {
    o.levels = {{4000, nullptr}, {1000, nullptr}, {250, nullptr}};
    return o;
  };
  const std::vector<PlannedObject> objects = {withLevels(boxAt({0, 0, -3})),
                                              withLevels(boxAt({0, 0, -5})),
                                              withLevels(boxAt({0, 0, -40})), boxAt({0, 0, -40})};
  // 128 pixels per unit of tangent: a 256-pixel 90-degree view, the numbers of the capture test
  // above (level 0 at 3 units, 1 at 5, 2 at 40).
  PlannerSettings settings;
  settings.viewLod = 0.5f;
  const std::vector<DrawItem> draws = planViewDraws(objects, {0, 0, 0}, 128.0f, settings);
  ASSERT_EQ(draws.size(), 4u);
  EXPECT_EQ(draws[0].lod, 0);
  EXPECT_EQ(draws[1].lod, 1);
  EXPECT_EQ(draws[2].lod, 2);
  EXPECT_EQ(draws[2].triangles, 250u);
  EXPECT_EQ(draws[3].lod, 0);  // one level only
  for (size_t i = 0; i < draws.size(); ++i) EXPECT_EQ(draws[i].object, static_cast<int>(i));
  // Twice the pixels per tangent (a view twice as tall) wants four times the triangles.
  EXPECT_EQ(planViewDraws(objects, {0, 0, 0}, 256.0f, settings)[2].lod, 2);
  EXPECT_EQ(planViewDraws(objects, {0, 0, 0}, 256.0f, settings)[1].lod, 0);
  // Off (the default): full detail, every object, as the course draws them.
  for (const DrawItem& d : planViewDraws(objects, {0, 0, 0}, 128.0f, {})) EXPECT_EQ(d.lod, 0);
}

TEST(FramePlanner, DrawsOnlyTheChunksAFaceCanSee) {
  // One object whose two chunks sit on either side of the probe.
  const std::vector<MeshChunk> chunks = {
      {{0, 300}, {{4, -1, -1}, {6, 1, 1}}},      // +X side, 100 triangles
      {{300, 600}, {{-6, -1, -1}, {-4, 1, 1}}},  // -X side, 200 triangles
  };
  PlannedObject wide;
  wide.localBounds = {{-6, -1, -1}, {6, 1, 1}};
  wide.levels = {{300, &chunks}};
  FramePlanner planner;
  const FramePlan plan = planner.plan({mirrorAt({0, 0, 0}), wide}, {}, {});
  const FacePlan& px = plan.probes[0].faces[kPX];
  const FacePlan& nx = plan.probes[0].faces[kNX];
  ASSERT_EQ(px.draws.size(), 1u);
  ASSERT_EQ(px.draws[0].ranges.size(), 1u);
  EXPECT_EQ(px.draws[0].ranges[0].first, 0u);
  EXPECT_EQ(px.draws[0].triangles, 100u);
  ASSERT_EQ(nx.draws.size(), 1u);
  EXPECT_EQ(nx.draws[0].ranges[0].first, 300u);
  EXPECT_EQ(nx.draws[0].triangles, 200u);
  // The object's box reaches into +Y (it is 2 tall around the probe's height) but no chunk is
  // beyond the near plane there: not drawn at all.
  EXPECT_TRUE(plan.probes[0].faces[kPY].draws.empty());
}

}  // namespace
}  // namespace reflect
