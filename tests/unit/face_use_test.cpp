// The face-use view's rule: a pixel's face is GL's cube face selection (cubeFaceCoord) of the
// direction the shader looked up along, marked by the lookup pass's alpha; traced pixels read no
// face; everything else is dimmed; the legend counts what was painted.
#include <gtest/gtest.h>

#include "core/face_use.h"

namespace reflect {
namespace {

glm::vec4 probeLookup(float x, float y, float z) {
  return {x, y, z, kLookupMarkProbe};
}

TEST(FaceUse, APixelsFaceIsTheCubeFaceRuleOfItsLookupDirection) {
  EXPECT_EQ(faceOfLookup(probeLookup(1.0f, 0.2f, -0.3f)), 0);
  EXPECT_EQ(faceOfLookup(probeLookup(-0.9f, 0.2f, 0.1f)), 1);
  EXPECT_EQ(faceOfLookup(probeLookup(0.1f, 0.5f, 0.2f)), 2);
  EXPECT_EQ(faceOfLookup(probeLookup(0.1f, -0.5f, 0.2f)), 3);
  EXPECT_EQ(faceOfLookup(probeLookup(0.3f, 0.2f, 0.31f)), 4);
  EXPECT_EQ(faceOfLookup(probeLookup(0.3f, 0.2f, -0.31f)), 5);
  // Ties go as llvmpipe and Direct3D 10 break them (core/cube_sampling.h): Z over Y over X.
  EXPECT_EQ(faceOfLookup(probeLookup(0.5f, 0.5f, 0.0f)), 2);
  EXPECT_EQ(faceOfLookup(probeLookup(0.5f, 0.5f, -0.5f)), 5);
  // The pass's alpha says whose the pixel is: a traced ray, or no lookup at all (a colour).
  EXPECT_EQ(faceOfLookup({0.0f, 0.0f, 1.0f, kLookupMarkTraced}), -1);
  EXPECT_EQ(faceOfLookup({0.0f, 0.0f, 1.0f, 1.0f}), -2);
  EXPECT_EQ(faceOfLookup({0.0f, 0.0f, 1.0f, 0.0f}), -2);
}

TEST(FaceUse, PaintsEachLookupInItsFacesColourTracedGreyAndDimsTheRest) {
  RgbaImage frame;
  frame.width = 4;
  frame.height = 1;
  frame.pixels = {90, 60, 30, 255, 90, 60, 30, 255, 90, 60, 30, 255, 90, 60, 30, 255};
  const std::vector<glm::vec4> lookups = {probeLookup(0.0f, 0.0f, -1.0f),
                                          probeLookup(1, 0, 0),
                                          {0, 0, 0, kLookupMarkTraced},
                                          {0.2f, 0.4f, 0.6f, 1.0f}};
  const FaceUseCounts counts = paintFaceUse(frame, lookups);
  const std::vector<uint8_t> expected = {240, 220, 40,  255, 230, 40, 40, 255,
                                         150, 150, 150, 255, 30,  20, 10, 255};
  EXPECT_EQ(frame.pixels, expected);
  EXPECT_EQ(counts.faces[5], 1u);
  EXPECT_EQ(counts.faces[0], 1u);
  EXPECT_EQ(counts.faces[2], 0u);
  EXPECT_EQ(counts.traced, 1u);
}

TEST(FaceUse, TheLegendSaysHowManyPixelsEachFaceServesAndWhatTheFrameDidToIt) {
  FaceMark captured;
  captured.captured = true;
  FaceMark stale;
  stale.captured = false;
  stale.ageFrames = 3;
  FaceMark empty;
  empty.captured = false;
  empty.everCaptured = false;
  EXPECT_EQ(faceUseLine(0, 5996, captured), "+X  5996 PX  CAPTURED");
  EXPECT_EQ(faceUseLine(3, 0, stale), "-Y  0 PX  STALE 3 FRAMES");
  EXPECT_EQ(faceUseLine(5, 0, empty), "-Z  0 PX  EMPTY");
}

TEST(FaceUse, TheViewKeepsThePaintedPixelsOutsideItsTitleAndLegend) {
  RgbaImage frame;
  frame.width = 300;
  frame.height = 200;
  frame.pixels.assign(300u * 200u * 4u, 200);
  std::vector<glm::vec4> lookups(300u * 200u, glm::vec4(0.0f));
  lookups[100u * 300u + 250u] = probeLookup(0.0f, 1.0f, 0.1f);  // (250, 100): +Y
  const RgbaImage view = composeFaceUse(frame, lookups, {}, "FACE USE");
  EXPECT_EQ(std::vector<uint8_t>(view.at(250, 100), view.at(250, 100) + 4),
            std::vector<uint8_t>(kFaceUseColours[2].begin(), kFaceUseColours[2].end()));
  EXPECT_EQ(view.at(250, 150)[0], 200 / 3);  // an unlooked pixel, dimmed
  EXPECT_EQ(view.at(2, 2)[0], 24);           // the title's panel
  EXPECT_EQ(view.at(2, 197)[0], 24);         // the legend's panel
}

}  // namespace
}  // namespace reflect
