// The faces view's marks follow the plans: a redrawn face is captured at age 0, a face left
// alone ages a frame per plan, a face never drawn is empty, and a probe that stops being
// captured (traced, or gone) is forgotten.
#include <gtest/gtest.h>

#include "core/face_ages.h"

namespace reflect {
namespace {

FramePlan planRedrawing(int reflector, std::initializer_list<int> faces) {
  FramePlan plan;
  ProbePlan probe;
  probe.reflector = reflector;
  for (int face : faces) {
    FacePlan f;
    f.face = face;
    probe.faces.push_back(f);
  }
  plan.probes.push_back(probe);
  return plan;
}

TEST(FaceAges, RedrawnFacesAreFreshAndTheOthersAge) {
  FaceAges ages;
  ages.advance(planRedrawing(2, {0, 1, 2, 3, 4, 5}));
  for (const FaceMark& mark : ages.marks(2)) {
    EXPECT_TRUE(mark.captured);
    EXPECT_EQ(mark.ageFrames, 0);
  }
  ages.advance(planRedrawing(2, {4}));
  ages.advance(planRedrawing(2, {4, 5}));
  const std::array<FaceMark, 6> marks = ages.marks(2);
  EXPECT_EQ(faceStatus(marks[0]), "STALE 2 FRAMES");
  EXPECT_EQ(faceStatus(marks[4]), "CAPTURED");
  EXPECT_EQ(faceStatus(marks[5]), "CAPTURED");
}

TEST(FaceAges, AFaceNeverDrawnIsEmptyAndAProbeNotCapturedIsForgotten) {
  FaceAges ages;
  ages.advance(planRedrawing(1, {2}));
  EXPECT_EQ(faceStatus(ages.marks(1)[2]), "CAPTURED");
  EXPECT_EQ(faceStatus(ages.marks(1)[0]), "EMPTY");
  EXPECT_EQ(faceStatus(ages.marks(7)[0]), "EMPTY");  // no such probe
  ages.advance(FramePlan{});                         // traced this frame: no probe
  EXPECT_EQ(faceStatus(ages.marks(1)[2]), "EMPTY");
}

}  // namespace
}  // namespace reflect
