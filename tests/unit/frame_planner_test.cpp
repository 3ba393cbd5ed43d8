// Each rule of the frame planner, on small synthetic scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <glm/gtc/matrix_transform.hpp>

#include "core/frame_planner.h"
#include "core/frustum.h"
#include "planned_boxes.h"

namespace reflect {
namespace {

using testing::boxAt;
using testing::facesOf;
using testing::kNX;
using testing::kNY;
using testing::kNZ;
using testing::kPX;
using testing::kPY;
using testing::kPZ;
using testing::kUnitBox;
using testing::mirrorAt;
using testing::objectsIn;

TEST(FramePlanner, NoProbeWithoutReflectiveObjects) {
  FramePlanner planner;
  const FramePlan plan = planner.plan({boxAt({3, 0, 0}), boxAt({0, 0, 3})}, {}, {});
  EXPECT_TRUE(plan.probes.empty());
  EXPECT_EQ(plan.facesCaptured(), 0);
}

TEST(FramePlanner, CullsObjectsPerFace) {
  FramePlanner planner;
  // 0: mirror at origin; 1: box on +X; 2: box on the +X/+Z edge; 3: a floor below everything.
  PlannedObject floor = boxAt({0, -3, 0});
  floor.model = glm::scale(glm::translate(glm::mat4(1.0f), {0, -3, 0}), {200, 0.01f, 200});
  const FramePlan plan =
      planner.plan({mirrorAt({0, 0, 0}), boxAt({5, 0, 0}), boxAt({4, 0, 4}), floor}, {}, {});
  ASSERT_EQ(plan.probes.size(), 1u);
  const ProbePlan& probe = plan.probes[0];
  EXPECT_EQ(facesOf(probe), (std::vector<int>{0, 1, 2, 3, 4, 5}));  // first frame: all
  EXPECT_EQ(objectsIn(probe, kPX), (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(objectsIn(probe, kPZ), (std::vector<int>{2, 3}));
  EXPECT_EQ(objectsIn(probe, kNX), (std::vector<int>{3}));
  EXPECT_EQ(objectsIn(probe, kPY), (std::vector<int>{}));  // the floor is below the probe
  EXPECT_EQ(objectsIn(probe, kNY), (std::vector<int>{3}));
}

TEST(FramePlanner, NearAndFarPlanesCull) {
  const glm::vec3 c(0.0f);
  EXPECT_FALSE(faceMaySee(c, kPX, 1.0f, 100.0f,
                          transformBounds(kUnitBox, glm::translate(glm::mat4(1.0f), {200, 0, 0}))));
  EXPECT_TRUE(
      faceMaySee(c, kPX, 1.0f, 100.0f,
                 transformBounds(kUnitBox, glm::translate(glm::mat4(1.0f), {100.3f, 0, 0}))));
  EXPECT_FALSE(faceMaySee(c, kPX, 1.0f, 100.0f,
                          transformBounds(kUnitBox, glm::scale(glm::mat4(1.0f), glm::vec3(0.5f)))));
}

TEST(FramePlanner, StaticSceneCapturesOnce) {
  FramePlanner planner;
  const std::vector<PlannedObject> scene = {mirrorAt({0, 0, 0}), boxAt({5, 0, 0}),
                                            boxAt({0, 0, -5})};
  EXPECT_EQ(planner.plan(scene, {}, {}).facesCaptured(), 6);
  for (int frame = 0; frame < 5; ++frame) EXPECT_EQ(planner.plan(scene, {}, {}).facesCaptured(), 0);
}

TEST(FramePlanner, RedrawsOnlyFacesWhereSomethingMoved) {
  FramePlanner planner;
  std::vector<PlannedObject> scene = {mirrorAt({0, 0, 0}), boxAt({5, 0, 0}), boxAt({0, 0, -5})};
  planner.plan(scene, {}, {});
  scene[1] = boxAt({5, 0.5f, 0});  // moves within +X
  FramePlan plan = planner.plan(scene, {}, {});
  EXPECT_EQ(facesOf(plan.probes[0]), (std::vector<int>{kPX}));
  EXPECT_EQ(objectsIn(plan.probes[0], kPX), (std::vector<int>{1}));
  // Moves from +X to +Z: +X must be redrawn to erase it, +Z to show it.
  scene[1] = boxAt({0, 0, 5});
  plan = planner.plan(scene, {}, {});
  EXPECT_EQ(facesOf(plan.probes[0]), (std::vector<int>{kPX, kPZ}));
  EXPECT_EQ(objectsIn(plan.probes[0], kPX), (std::vector<int>{}));
  // A colour change is a change too.
  scene[2].colour = glm::vec3(0.5f);
  EXPECT_EQ(facesOf(planner.plan(scene, {}, {}).probes[0]), (std::vector<int>{kNZ}));
  // And so is a new mesh.
  scene[2].meshRevision = 7;
  EXPECT_EQ(facesOf(planner.plan(scene, {}, {}).probes[0]), (std::vector<int>{kNZ}));
}

TEST(FramePlanner, ProbeMoveOrOptionChangeRedrawsEverything) {
  FramePlanner planner;
  std::vector<PlannedObject> scene = {mirrorAt({0, 0, 0}), boxAt({5, 0, 0})};
  planner.plan(scene, {}, {});
  scene[0] = mirrorAt({0, 0.1f, 0});
  EXPECT_EQ(planner.plan(scene, {}, {}).facesCaptured(), 6);
  EXPECT_EQ(planner.plan(scene, {}, {}).facesCaptured(), 0);
  CaptureContext moved;
  moved.lightingEye = glm::vec3(0, 1, 7);  // the course lights captures from the main eye
  EXPECT_EQ(planner.plan(scene, moved, {}).facesCaptured(), 6);
  CaptureContext bigger = moved;
  bigger.faceSize = 512;
  EXPECT_EQ(planner.plan(scene, bigger, {}).facesCaptured(), 6);
  planner.invalidate();
  EXPECT_EQ(planner.plan(scene, bigger, {}).facesCaptured(), 6);
}

TEST(FramePlanner, EveryCaptureInputIsComparedByValue) {
  const std::vector<PlannedObject> scene = {mirrorAt({0, 0, 0}), boxAt({5, 0, 0})};
  // Each change of one input, from the same starting context: all six faces, once.
  const std::vector<void (*)(CaptureContext&)> changes = {
      [](CaptureContext& c) { c.light.position.x += 1.0f; },
      [](CaptureContext& c) { c.light.shininess = 20.0f; },
      [](CaptureContext& c) { c.clearColour = glm::vec3(0.0f); },
      [](CaptureContext& c) { c.skyboxContent = 42; },
      [](CaptureContext& c) { c.accuracy.search = Search::Plain; },
      [](CaptureContext& c) { c.captureLod = 0.5f; },
      [](CaptureContext& c) { c.near = 0.5f; },
  };
  for (auto change : changes) {
    FramePlanner planner;
    CaptureContext context;
    planner.plan(scene, context, {});
    ASSERT_EQ(planner.plan(scene, context, {}).facesCaptured(), 0);
    change(context);
    EXPECT_EQ(planner.plan(scene, context, {}).facesCaptured(), 6);
    EXPECT_EQ(planner.plan(scene, context, {}).facesCaptured(), 0);
    CaptureContext same = context;  // an equal value is no change
    EXPECT_EQ(planner.plan(scene, same, {}).facesCaptured(), 0);
  }
}

TEST(FramePlanner, AMaterialOrLevelChangeRedrawsTheFacesThatShowIt) {
  FramePlanner planner;
  std::vector<PlannedObject> scene = {mirrorAt({0, 0, 0}), mirrorAt({5, 0, 0})};
  planner.plan(scene, {}, {});
  planner.plan(scene, {}, {});  // the one bounce
  ASSERT_EQ(planner.plan(scene, {}, {}).facesCaptured(), 0);
  scene[1].look.reflection = 0.5f;
  const FramePlan plan = planner.plan(scene, {}, {});
  ASSERT_EQ(plan.probes.size(), 2u);
  EXPECT_EQ(facesOf(plan.probes[0]), (std::vector<int>{kPX}));  // the face that shows mirror 1
  EXPECT_TRUE(plan.probes[1].faces.empty());
  // Mirror 0's cube changed with it, so mirror 1's face that shows mirror 0 follows (one bounce).
  EXPECT_EQ(facesOf(planner.plan(scene, {}, {}).probes[1]), (std::vector<int>{kNX}));
  EXPECT_EQ(planner.plan(scene, {}, {}).facesCaptured(), 0);
  // A level of detail built after the first capture: the faces that show the object again.
  scene[1].levels = {PlannedLevel{100, nullptr}, PlannedLevel{25, nullptr}};
  EXPECT_EQ(facesOf(planner.plan(scene, {}, {}).probes[0]), (std::vector<int>{kPX}));
}

TEST(FramePlanner, LayoutNamesEachObjectsProbeWithoutCapturing) {
  PlannedObject a = mirrorAt({-1, 0, 0}), b = mirrorAt({1, 0, 0});
  a.probeGroup = b.probeGroup = 0;
  PlannedObject course = mirrorAt({0, 0, 9});
  course.probeCentre = glm::vec3(0.0f);  // an explicit capture point wins over the bounds
  const FramePlan plan = FramePlanner::layout({a, b, boxAt({0, 0, -6}), course}, {});
  ASSERT_EQ(plan.probes.size(), 2u);
  EXPECT_EQ(plan.facesCaptured(), 0);
  EXPECT_EQ(plan.probeOf(1), &plan.probes[0]);
  EXPECT_EQ(plan.probeOf(2), nullptr);
  ASSERT_NE(plan.probeOf(3), nullptr);
  EXPECT_EQ(plan.probeOf(3)->centre, glm::vec3(0.0f));
  EXPECT_EQ(plan.probeOf(3)->reflector, 3);
}

TEST(FramePlanner, ExcludesEachReflectorFromItsOwnProbeOnly) {
  FramePlanner planner;
  const FramePlan plan = planner.plan({mirrorAt({0, 0, 0}), mirrorAt({5, 0, 0})}, {}, {});
  ASSERT_EQ(plan.probes.size(), 2u);
  EXPECT_EQ(plan.probes[0].reflector, 0);
  EXPECT_EQ(plan.probes[1].reflector, 1);
  for (const ProbePlan& probe : plan.probes) {
    for (const FacePlan& f : probe.faces) {
      for (const DrawItem& d : f.draws) EXPECT_NE(d.object, probe.reflector);
    }
  }
  EXPECT_EQ(objectsIn(plan.probes[0], kPX), (std::vector<int>{1}));  // sees the other mirror
  EXPECT_EQ(objectsIn(plan.probes[1], kNX), (std::vector<int>{0}));
}

TEST(FramePlanner, TwoMirrorsSettleAfterOneBounce) {
  FramePlanner planner;
  const std::vector<PlannedObject> scene = {mirrorAt({0, 0, 0}), mirrorAt({5, 0, 0})};
  EXPECT_EQ(planner.plan(scene, {}, {}).facesCaptured(), 12);
  // Each mirror's cube changed, so the face of the other that shows it is redrawn once...
  const FramePlan bounce = planner.plan(scene, {}, {});
  EXPECT_EQ(bounce.facesCaptured(), 2);
  // ...and that redraw does not trigger the first one again.
  EXPECT_EQ(planner.plan(scene, {}, {}).facesCaptured(), 0);
}

TEST(FramePlanner, NeighboursCanShareOneProbe) {
  PlannedObject a = mirrorAt({-1, 0, 0}), b = mirrorAt({1, 0, 0}), c = mirrorAt({0, 0, 9});
  a.probeGroup = b.probeGroup = 3;
  FramePlanner planner;
  const FramePlan plan = planner.plan({a, b, c, boxAt({0, 0, -6})}, {}, {});
  ASSERT_EQ(plan.probes.size(), 2u);
  EXPECT_EQ(plan.probes[0].reflector, 0);
  EXPECT_EQ(plan.probes[0].members, (std::vector<int>{0, 1}));
  EXPECT_EQ(plan.probes[0].centre, glm::vec3(0, 0, 0));  // centre of the joint bounds
  EXPECT_EQ(plan.probes[1].members, (std::vector<int>{2}));
  for (const FacePlan& f : plan.probes[0].faces) {
    for (const DrawItem& d : f.draws) EXPECT_TRUE(d.object == 2 || d.object == 3);
  }
}

TEST(FramePlanner, EveryFramePolicyIsTheCourseScheme) {
  FramePlanner planner;
  PlannerSettings original;
  original.policy = UpdatePolicy::EveryFrame;
  const std::vector<PlannedObject> scene = {boxAt({5, 0, 0}), mirrorAt({0, 0, 0}),
                                            boxAt({0, 9, 0})};
  for (int frame = 0; frame < 3; ++frame) {
    const FramePlan plan = planner.plan(scene, {}, original);
    ASSERT_EQ(plan.facesCaptured(), 6);
    for (int face = 0; face < 6; ++face) {
      EXPECT_EQ(objectsIn(plan.probes[0], face), (std::vector<int>{0, 2}));  // no culling
    }
  }
}

TEST(FramePlanner, TimeSlicingBoundsFacesPerFrameAndReachesEveryFace) {
  FramePlanner planner;
  PlannerSettings sliced;
  sliced.policy = UpdatePolicy::TimeSliced;
  sliced.facesPerFrame = 2;
  EXPECT_EQ(sliced.maxStalenessFrames(), 2);
  const std::vector<PlannedObject> scene = {mirrorAt({0, 0, 0}), boxAt({5, 0, 0})};
  std::vector<int> seen;
  for (int frame = 0; frame < 3; ++frame) {
    const FramePlan plan = planner.plan(scene, {}, sliced);
    EXPECT_EQ(plan.facesCaptured(), 2);
    for (int f : facesOf(plan.probes[0])) seen.push_back(f);
  }
  std::sort(seen.begin(), seen.end());
  EXPECT_EQ(seen, (std::vector<int>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(planner.plan(scene, {}, sliced).facesCaptured(), 0);  // all fresh now
}

TEST(FramePlanner, EveryNFramesCapturesOnlyOnItsFrames) {
  FramePlanner planner;
  PlannerSettings everyThird;
  everyThird.policy = UpdatePolicy::EveryNFrames;
  everyThird.everyN = 3;
  EXPECT_EQ(everyThird.maxStalenessFrames(), 2);
  std::vector<PlannedObject> scene = {mirrorAt({0, 0, 0}), boxAt({5, 0, 0})};
  std::vector<int> faces;
  for (int frame = 0; frame < 7; ++frame) {
    scene[1] = boxAt({5, 0.01f * static_cast<float>(frame), 0});  // moves every frame
    faces.push_back(planner.plan(scene, {}, everyThird).facesCaptured());
  }
  EXPECT_EQ(faces, (std::vector<int>{6, 0, 0, 1, 0, 0, 1}));
}

// With everything moving, every face is stale every frame: a policy that spreads the redraws must
// still reach each face within its bound (maxStalenessFrames), and not starve any.
void expectNoFaceStarves(PlannerSettings settings) {
  FramePlanner planner;
  std::array<int, 6> last;
  last.fill(-1);  // "captured" just before the first frame: staleness counts from the start
  for (int frame = 0; frame < 24; ++frame) {
    std::vector<PlannedObject> scene = {mirrorAt({0, 0, 0})};
    const float wobble = 0.01f * static_cast<float>(frame);
    for (const glm::vec3& d : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0),
                               glm::vec3(0, -1, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)}) {
      scene.push_back(boxAt(5.0f * d + glm::vec3(wobble)));  // one in front of each face, moving
    }
    const FramePlan plan = planner.plan(scene, {}, settings);
    for (int f : facesOf(plan.probes[0])) last[static_cast<size_t>(f)] = frame;
    for (int f = 0; f < 6; ++f) {
      EXPECT_LE(frame - last[static_cast<size_t>(f)], settings.maxStalenessFrames())
          << policyName(settings.policy) << ": face " << f << " at frame " << frame;
    }
  }
}

TEST(FramePlanner, NoFaceStarvesWhenEverythingMoves) {
  for (int k = 1; k <= 6; ++k) {
    PlannerSettings sliced;
    sliced.policy = UpdatePolicy::TimeSliced;
    sliced.facesPerFrame = k;
    expectNoFaceStarves(sliced);
  }
  for (int n : {1, 2, 3, 4, 7}) {
    PlannerSettings everyN;
    everyN.policy = UpdatePolicy::EveryNFrames;
    everyN.everyN = n;
    expectNoFaceStarves(everyN);
  }
  for (UpdatePolicy exact : {UpdatePolicy::EveryFrame, UpdatePolicy::WhenChanged}) {
    PlannerSettings s;
    s.policy = exact;
    expectNoFaceStarves(s);  // bound 0: every face, every frame
  }
}

TEST(FramePlanner, PolicyNamesRoundTrip) {
  for (UpdatePolicy p : {UpdatePolicy::EveryFrame, UpdatePolicy::WhenChanged,
                         UpdatePolicy::TimeSliced, UpdatePolicy::EveryNFrames}) {
    UpdatePolicy parsed = UpdatePolicy::WhenChanged;
    ASSERT_TRUE(parsePolicy(policyName(p), &parsed));
    EXPECT_EQ(parsed, p);
  }
  UpdatePolicy unused;
  EXPECT_FALSE(parsePolicy("sometimes", &unused));
  EXPECT_EQ(PlannerSettings{}.maxStalenessFrames(), 0);
}

}  // namespace
}  // namespace reflect
