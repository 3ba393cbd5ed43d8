// search: planned. The cost model (core/method_cost.h): costs in, a choice out; and the frame
// planner's use of it: a traced reflector has no probe and no face, a captured one its faces.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "core/frame_planner.h"
#include "core/method_cost.h"

namespace reflect {
namespace {

MethodCosts unitCosts() {
  MethodCosts c;
  c.tracePixel = 1.0;
  c.tracePixelLevel = 0.5;
  c.generalFactor = 2.0;
  c.face = 10.0;
  c.triangle = 0.01;
  c.texel = 0.001;
  c.searchPixel = 0.25;
  c.hysteresis = 1.2;
  return c;
}

TEST(MethodCost, TheModelIsLinearInTheCounts) {
  const MethodCosts c = unitCosts();
  // 100 pixels, 1024 triangles: 10 levels, 1 + 0.5 x 10 = 6 a pixel.
  EXPECT_DOUBLE_EQ(traceCost({100.0, 1024.0, false}, c), 600.0);
  EXPECT_DOUBLE_EQ(traceCost({100.0, 1024.0, true}, c), 1200.0);
  // 3 faces, 2000 triangles, 4000 texels, 100 pixels searched: 30 + 20 + 4 + 25.
  EXPECT_DOUBLE_EQ(captureCost({3.0, 2000.0, 4000.0, 100.0}, c), 79.0);
}

TEST(MethodCost, TheCheaperWinsPastTheHysteresis) {
  const MethodCosts c = unitCosts();
  EXPECT_EQ(chooseMethod(10.0, 20.0, Method::Capture, c), Method::Trace);
  EXPECT_EQ(chooseMethod(10.0, 11.0, Method::Capture, c), Method::Capture);  // within 1.2x
  EXPECT_EQ(chooseMethod(11.0, 10.0, Method::Trace, c), Method::Trace);
  EXPECT_EQ(chooseMethod(20.0, 10.0, Method::Trace, c), Method::Capture);
  EXPECT_EQ(chooseMethod(10.0, 10.0, Method::Trace, c), Method::Trace);
}

TEST(MethodCost, ScreenPixelsOfASphere) {
  const PlannerView view{glm::vec3(0.0f), 400.0f, 800.0f * 800.0f};
  // Radius 1 at distance 10: tan = 1 / sqrt(99), 40.2 pixels across the radius.
  const float tangent = 1.0f / std::sqrt(99.0f);
  EXPECT_NEAR(screenPixels({0, 0, -10}, 1.0f, view), 3.14159265f * 160000.0f * tangent * tangent,
              0.5f);
  EXPECT_EQ(screenPixels({0, 0, -0.5f}, 1.0f, view), 800.0f * 800.0f);  // inside it
  EXPECT_EQ(screenPixels({0, 0, -10}, 1.0f, PlannerView{}), 0.0f);      // no view
}

// A mirror at the origin, a moving figure beside it and a ground, as the planner sees them.
std::vector<PlannedObject> sceneWithMirror(Material material = Material::Mirror) {
  PlannedObject mirror;
  mirror.localBounds = {glm::vec3(-1.0f), glm::vec3(1.0f)};
  mirror.probed = true;
  mirror.look.material = material;
  PlannedObject figure;
  figure.localBounds = {glm::vec3(-0.5f), glm::vec3(0.5f)};
  figure.model = glm::translate(glm::mat4(1.0f), {3, 0, 0});
  figure.levels = {PlannedLevel{5000, nullptr}};
  PlannedObject ground;
  ground.localBounds = {{-1, 0, -1}, {1, 0, 1}};
  ground.model = glm::scale(glm::translate(glm::mat4(1.0f), {0, -2, 0}), {50, 1, 50});
  ground.levels = {PlannedLevel{2, nullptr}};
  return {mirror, figure, ground};
}

CaptureContext planned() {
  CaptureContext context;
  context.accuracy.search = Search::Planned;
  return context;
}

const PlannerView kView{glm::vec3(0, 0, 7), 571.0f, 800.0f * 800.0f};

// Costs under which tracing, or capturing, is clearly the cheaper.
MethodCosts traceCheap() {
  MethodCosts c = unitCosts();
  c.tracePixel = 1e-6;
  c.tracePixelLevel = 0.0;
  return c;
}
MethodCosts captureCheap() {
  MethodCosts c = unitCosts();
  c.face = c.triangle = c.texel = c.searchPixel = 0.0;
  return c;
}

TEST(MethodChoice, TracingCheaperMeansNoProbeAndNoFace) {
  FramePlanner planner;
  planner.setCosts(traceCheap());
  const FramePlan plan = planner.plan(sceneWithMirror(), planned(), {}, kView);
  EXPECT_TRUE(plan.probes.empty());
  ASSERT_EQ(plan.traced.size(), 1u);
  EXPECT_EQ(plan.traced[0].reflector, 0);
  EXPECT_TRUE(plan.traces(0));
  EXPECT_EQ(plan.probeOf(0), nullptr);
  EXPECT_EQ(plan.layoutOf(0), &plan.traced[0]);
  EXPECT_EQ(plan.facesCaptured(), 0);
  ASSERT_EQ(planner.choices().size(), 1u);
  EXPECT_EQ(planner.choices()[0].method, Method::Trace);
  EXPECT_LT(planner.choices()[0].traceMs, planner.choices()[0].captureMs);
}

TEST(MethodChoice, CapturingCheaperMeansAProbeWithItsFaces) {
  FramePlanner planner;
  planner.setCosts(captureCheap());
  const FramePlan plan = planner.plan(sceneWithMirror(), planned(), {}, kView);
  EXPECT_TRUE(plan.traced.empty());
  ASSERT_EQ(plan.probes.size(), 1u);
  EXPECT_EQ(plan.facesCaptured(), 6);  // the first frame: every face
  EXPECT_EQ(planner.choices()[0].method, Method::Capture);
}

TEST(MethodChoice, TheWorkItWeighsIsTheFramesWork) {
  FramePlanner planner;
  planner.setCosts(unitCosts());
  planner.plan(sceneWithMirror(), planned(), {}, kView);
  const MethodChoice first = planner.choices()[0];
  // The mirror's disc: radius sqrt(3) (its box's corner) seen from 7 units.
  const float r = std::sqrt(3.0f);
  EXPECT_FLOAT_EQ(static_cast<float>(first.trace.pixels), screenPixels(glm::vec3(0.0f), r, kView));
  EXPECT_DOUBLE_EQ(first.trace.triangles, 5002.0);
  EXPECT_FALSE(first.trace.general);  // the others are Phong
  // The first frame counts every face that shows something: the figure on +X, the ground below.
  EXPECT_GE(first.capture.faces, 2.0);
  EXPECT_EQ(first.capture.pixels, first.trace.pixels);

  // Nothing moves: no face would be redrawn, and only the search remains of a capture's cost.
  planner.plan(sceneWithMirror(), planned(), {}, kView);
  const MethodChoice still = planner.choices()[0];
  EXPECT_EQ(still.capture.faces, 0.0);
  EXPECT_EQ(still.capture.triangles, 0.0);
  EXPECT_DOUBLE_EQ(still.captureMs, still.capture.pixels * unitCosts().searchPixel);

  // The figure moves: the faces that show it are redrawn, with its triangles.
  std::vector<PlannedObject> moved = sceneWithMirror();
  moved[1].model = glm::translate(glm::mat4(1.0f), {3, 0.1f, 0});
  planner.plan(moved, planned(), {}, kView);
  const MethodChoice moving = planner.choices()[0];
  EXPECT_GE(moving.capture.faces, 1.0);
  EXPECT_GE(moving.capture.triangles, 5000.0);
}

TEST(MethodChoice, AnotherReflectorInViewNeedsTheGeneralTracer) {
  FramePlanner planner;
  planner.setCosts(unitCosts());
  std::vector<PlannedObject> objects = sceneWithMirror();
  objects[1].look.material = Material::Glass;
  objects[1].probed = true;
  planner.plan(objects, planned(), {}, kView);
  ASSERT_EQ(planner.choices().size(), 2u);
  EXPECT_TRUE(planner.choices()[0].trace.general);
}

// One rule for the tracer's program and its cost: a mirror alone among Phong objects takes the
// Phong-only tracer; glass (its own far side) and a mirror sharing its probe with another (they
// see each other) take the general one, costed so and recorded in the plan for the renderer.
TEST(MethodChoice, TheGeneralTracerIsDecidedOnceAndRecordedInThePlan) {
  FramePlanner planner;
  planner.setCosts(unitCosts());
  CaptureContext exact;
  exact.accuracy.search = Search::Exact;
  FramePlan plan = planner.plan(sceneWithMirror(), exact, {}, kView);
  EXPECT_TRUE(plan.traces(0));
  EXPECT_FALSE(plan.tracesGeneral(0));

  plan = planner.plan(sceneWithMirror(Material::Glass), exact, {}, kView);
  EXPECT_TRUE(plan.tracesGeneral(0));

  std::vector<PlannedObject> pair = sceneWithMirror();
  pair.push_back(pair[0]);
  pair.back().model = glm::translate(glm::mat4(1.0f), {0, 0, -3});
  pair[0].probeGroup = pair.back().probeGroup = 7;  // one probe for both
  FramePlanner weighing;
  weighing.setCosts(traceCheap());
  plan = weighing.plan(pair, planned(), {}, kView);
  ASSERT_EQ(weighing.choices().size(), 1u);
  EXPECT_EQ(weighing.choices()[0].method, Method::Trace);
  EXPECT_TRUE(weighing.choices()[0].trace.general);  // they see each other: costed as general
  EXPECT_EQ(plan.generalTracers, (std::vector<int>{0, 3}));
}

TEST(MethodChoice, WithoutAViewPlannedCaptures) {
  FramePlanner planner;
  const FramePlan plan = planner.plan(sceneWithMirror(), planned(), {});
  EXPECT_TRUE(plan.traced.empty());
  EXPECT_EQ(plan.probes.size(), 1u);
  EXPECT_TRUE(planner.choices().empty());
}

TEST(MethodChoice, TheExactSearchTracesEveryMirrorAndGlass) {
  FramePlanner planner;
  CaptureContext context;
  context.accuracy.search = Search::Exact;
  std::vector<PlannedObject> objects = sceneWithMirror();
  // A skybox-lit mirror has no probe; the exact mode traces it too.
  PlannedObject skyMirror = objects[0];
  skyMirror.probed = false;
  skyMirror.model = glm::translate(glm::mat4(1.0f), {0, 5, 0});
  objects.push_back(skyMirror);
  const FramePlan plan = planner.plan(objects, context, {});
  EXPECT_TRUE(plan.probes.empty());
  EXPECT_EQ(plan.facesCaptured(), 0);
  EXPECT_TRUE(plan.traces(0));
  EXPECT_TRUE(plan.traces(3));
  EXPECT_FALSE(plan.traces(1));
}

TEST(MethodChoice, ACubeTexturedObjectIsAlwaysCaptured) {
  FramePlanner planner;
  planner.setCosts(traceCheap());
  CaptureContext context = planned();
  for (Search search : {Search::Planned, Search::Exact}) {
    context.accuracy.search = search;
    const FramePlan plan =
        planner.plan(sceneWithMirror(Material::CubeTextured), context, {}, kView);
    EXPECT_TRUE(plan.traced.empty()) << searchName(search);
    EXPECT_EQ(plan.probes.size(), 1u) << searchName(search);
  }
}

TEST(MethodChoice, SwitchingBackToCaptureRedrawsEveryFace) {
  FramePlanner planner;
  planner.setCosts(traceCheap());
  planner.plan(sceneWithMirror(), planned(), {}, kView);
  planner.setCosts(captureCheap());
  // Nothing moved, but the trace kept no faces: all six are drawn.
  const FramePlan plan = planner.plan(sceneWithMirror(), planned(), {}, kView);
  ASSERT_EQ(plan.probes.size(), 1u);
  EXPECT_EQ(plan.facesCaptured(), 6);
  // And the next frame, still nothing moving, none.
  EXPECT_EQ(planner.plan(sceneWithMirror(), planned(), {}, kView).facesCaptured(), 0);
}

}  // namespace
}  // namespace reflect
