// Step through a frame: the step list is the plan's draws, in the renderer's order, with the
// plan's triangle counts, for every face (the course), a time-sliced frame, a two-layer probe and
// a frame whose reflector is traced (no capture at all).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/frame_steps.h"
#include "planned_boxes.h"

namespace reflect {
namespace {

// Boxes with three levels of detail, so that the steps' triangle counts tell the levels apart.
PlannedObject boxAt(glm::vec3 position) {
  PlannedObject o = testing::boxAt(position);
  o.levels = {{4000, nullptr}, {1000, nullptr}, {250, nullptr}};
  return o;
}

PlannedObject mirrorAt(glm::vec3 position) {
  PlannedObject o = testing::mirrorAt(position);
  o.levels = boxAt(position).levels;
  return o;
}

// The mirror at the origin; +X shows a box in front of another, -Z one box alone.
std::vector<PlannedObject> sceneObjects() {
  return {mirrorAt({0, 0, 0}), boxAt({3, 0, 0}), boxAt({8, 0, 0}), boxAt({0, 0, -5})};
}

CaptureContext contextWith(Search search, int layers) {
  CaptureContext context;
  context.accuracy.search = search;
  context.accuracy.layers = layers;
  return context;
}

// What the plan draws, counted from the plan itself: one pass a face, three with two layers, a
// pyramid per probe that stores depths, and the main pass.
size_t planDraws(const FramePlan& plan, const AccuracySettings& accuracy) {
  size_t draws = 1;
  for (const ProbePlan& probe : plan.probes) {
    for (const FacePlan& face : probe.faces) draws += face.layers == 2 ? 3 : 1;
    if (!probe.faces.empty() && capturesDepths(probe, accuracy)) ++draws;
  }
  return draws;
}

std::vector<DrawItem> mainDraws(const std::vector<PlannedObject>& objects) {
  return planViewDraws(objects, glm::vec3(0, 0, 10), 400.0f, PlannerSettings{});
}

TEST(FrameSteps, EveryFaceOfTheCourseIsOneStepThenTheMainPass) {
  FramePlanner planner;
  PlannerSettings settings;
  settings.policy = UpdatePolicy::EveryFrame;
  const CaptureContext context = contextWith(Search::Plain, 1);
  const FramePlan plan = planner.plan(sceneObjects(), context, settings);
  const std::vector<FrameStep> steps =
      frameSteps(plan, context.accuracy, mainDraws(sceneObjects()));
  ASSERT_EQ(steps.size(), 7u);  // six faces, one pass each (no depths stored), the main pass
  EXPECT_EQ(steps.size(), planDraws(plan, context.accuracy));
  for (int face = 0; face < 6; ++face) {
    const FrameStep& step = steps[static_cast<size_t>(face)];
    EXPECT_EQ(step.pass, StepPass::Colour);
    EXPECT_EQ(step.face, face);
    EXPECT_EQ(step.reflector, 0);
    // The course draws every other object whole into every face: 3 x 4000 triangles.
    EXPECT_EQ(step.triangles, 12000u);
    EXPECT_EQ(step.objects, 3);
  }
  EXPECT_EQ(
      steps[4].label,
      "colour (pass 1) into the probe of object 1, face +Z, layer 1: 3 objects, 12000 triangles");
  EXPECT_EQ(steps.back().pass, StepPass::Main);
  EXPECT_EQ(steps.back().objects, 4);
  EXPECT_EQ(steps.back().triangles, 16000u);
  EXPECT_EQ(steps.back().label, "main pass to the screen: 4 objects, 16000 triangles");
}

TEST(FrameSteps, TimeSlicedFramesStepThroughTheirFacesOnly) {
  FramePlanner planner;
  PlannerSettings settings;
  settings.policy = UpdatePolicy::TimeSliced;
  settings.facesPerFrame = 2;
  const CaptureContext context = contextWith(Search::Hierarchical, 1);
  for (int frame = 0; frame < 4; ++frame) {
    const FramePlan plan = planner.plan(sceneObjects(), context, settings);
    const std::vector<FrameStep> steps =
        frameSteps(plan, context.accuracy, mainDraws(sceneObjects()));
    EXPECT_EQ(steps.size(), planDraws(plan, context.accuracy)) << "frame " << frame;
    // Two faces and the pyramid of what they changed while faces are stale, then the main pass.
    EXPECT_EQ(steps.size(), frame < 3 ? 4u : 1u) << "frame " << frame;
    if (frame < 3) {
      EXPECT_EQ(steps[2].pass, StepPass::DepthPyramid);
    }
  }
}

TEST(FrameSteps, TwoLayerFacesDrawThreePassesInTheRenderersOrder) {
  FramePlanner planner;
  const CaptureContext context = contextWith(Search::Hierarchical, 2);
  const FramePlan plan = planner.plan(sceneObjects(), context, PlannerSettings{});
  ASSERT_EQ(plan.probes.size(), 1u);
  const std::vector<FrameStep> steps =
      frameSteps(plan, context.accuracy, mainDraws(sceneObjects()));
  EXPECT_EQ(steps.size(), planDraws(plan, context.accuracy));
  size_t index = 0;
  int twoLayerFaces = 0;
  for (const FacePlan& face : plan.probes[0].faces) {
    const std::vector<StepPass> expected =
        face.layers == 2
            ? std::vector<StepPass>{StepPass::Colour, StepPass::Backs, StepPass::SecondLayer}
            : std::vector<StepPass>{StepPass::Colour};
    twoLayerFaces += face.layers == 2 ? 1 : 0;
    for (StepPass pass : expected) {
      ASSERT_LT(index, steps.size());
      EXPECT_EQ(steps[index].pass, pass);
      EXPECT_EQ(steps[index].face, face.face);
      size_t triangles = 0;
      for (const DrawItem& d : pass == StepPass::SecondLayer ? face.secondLayerDraws : face.draws) {
        triangles += d.triangles;
      }
      EXPECT_EQ(steps[index].triangles, triangles);
      ++index;
    }
  }
  EXPECT_GE(twoLayerFaces, 1);  // +X: a box hides another
  EXPECT_EQ(steps[index].pass, StepPass::DepthPyramid);
  EXPECT_EQ(steps[index + 1].pass, StepPass::Main);
  EXPECT_EQ(index + 2, steps.size());
}

TEST(FrameSteps, ATracedReflectorCapturesNothingAndLeavesTheMainPass) {
  FramePlanner planner;
  const CaptureContext context = contextWith(Search::Exact, 2);
  const FramePlan plan = planner.plan(sceneObjects(), context, PlannerSettings{});
  ASSERT_EQ(plan.traced.size(), 1u);
  ASSERT_TRUE(plan.probes.empty());
  const std::vector<FrameStep> steps =
      frameSteps(plan, context.accuracy, mainDraws(sceneObjects()));
  ASSERT_EQ(steps.size(), 1u);
  EXPECT_EQ(steps[0].pass, StepPass::Main);
  EXPECT_EQ(steps.size(), planDraws(plan, context.accuracy));
}

}  // namespace
}  // namespace reflect
