// The course's own frame (src/course/course_frame.cpp) against the general renderer: two
// independent implementations of the course preset that must draw the same pixels, and the
// course path's golden image.
#include <gtest/gtest.h>

#include "app/headless_frames.h"
#include "core/presets.h"
#include "core/scene_file.h"
#include "course/course_frame.h"
#include "gl_fixture.h"
#include "golden_compare.h"

namespace reflect {
namespace {

std::unique_ptr<Demo> courseDemo(bool courseFile) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  const Preset& course = *findPreset("course");
  demo->setPlannerSettings(course.planner);
  EXPECT_EQ(demo->setAccuracySettings(course.accuracy), "");
  demo->allowCourseFrame(courseFile);
  return demo;
}

size_t differingPixels(const RgbaImage& a, const RgbaImage& b) {
  size_t differing = 0;
  for (size_t i = 0; i < a.pixels.size(); i += 4) {
    for (size_t c = 0; c < 3; ++c) {
      if (a.pixels[i + c] != b.pixels[i + c]) {
        ++differing;
        break;
      }
    }
  }
  return differing;
}

TEST(CourseFrame, DrawsThePixelsOfTheGeneralRendererAtThreeTimes) {
  auto course = courseDemo(true);
  auto general = courseDemo(false);
  // Held-out times, a wide frame (aspect 4:3) and a face size other than the scene's.
  for (double t : {0.7, 3.1, 6.4}) {
    auto fromCourse = renderFrameAt(*course, t, 400, 300);
    auto fromGeneral = renderFrameAt(*general, t, 400, 300);
    ASSERT_TRUE(fromCourse && fromGeneral);
    EXPECT_TRUE(course->lastFrame().course);
    EXPECT_FALSE(general->lastFrame().course);
    EXPECT_EQ(differingPixels(fromCourse.value(), fromGeneral.value()), 0u) << "t = " << t;
    // The mirror is really there and really reflects: the frames differ from one without it.
    EXPECT_EQ(course->lastStats().facesCaptured, 6);
    EXPECT_EQ(course->lastStats().probes, 1);
  }
}

TEST(CourseFrame, SmallFacesStillMatch) {
  auto course = courseDemo(true);
  auto general = courseDemo(false);
  EXPECT_EQ(course->setCubeFaceSize(32), "");
  EXPECT_EQ(general->setCubeFaceSize(32), "");
  ASSERT_EQ(course->initGraphics(), "");
  ASSERT_EQ(general->initGraphics(), "");
  auto a = renderFrameAt(*course, 1.9, 160, 160);
  auto b = renderFrameAt(*general, 1.9, 160, 160);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(differingPixels(a.value(), b.value()), 0u);
}

TEST(CourseFrame, MatchesItsGolden) {
  auto course = courseDemo(true);
  auto image = renderFrameAt(*course, 2.0, 512, 512);
  ASSERT_TRUE(image) << image.error();
  testing::expectMatchesGolden(image.value(), "course_ex12-2_t2.png",
                               testing::reflectorMask(makeDynamicReflectionScene(), 2.0, 512, 512));
}

TEST(CourseFrame, TheStatsCountWhatItDrew) {
  auto course = courseDemo(true);
  ASSERT_TRUE(renderFrameAt(*course, 1.0, 64, 64));
  const FrameStats& s = course->lastStats();
  EXPECT_EQ(s.captureDrawCalls, 6 * 3);  // six faces of ground, sonic and mario
  EXPECT_EQ(s.mainDrawCalls, 4);
  EXPECT_EQ(s.tracedReflectors, 0);
  EXPECT_TRUE(s.courseFrame);
  EXPECT_GE(s.frameMs, s.captureMs);
}

TEST(CourseFrame, TheViewsThatLookInsideUseTheGeneralRenderer) {
  auto course = courseDemo(true);
  course->setInsideView(InsideView::Faces, FacesChannel::Colour);
  ASSERT_TRUE(renderFrameAt(*course, 1.0, 64, 64));
  EXPECT_FALSE(course->lastFrame().course);
  course->setInsideView(InsideView::Off, FacesChannel::Colour);
  ASSERT_TRUE(renderFrameAt(*course, 1.0, 64, 64));
  EXPECT_TRUE(course->lastFrame().course);
}

TEST(CourseFrame, DrawsOnlyTheCoursesKindOfScene) {
  EXPECT_EQ(CourseFrame::whyNot(makeDynamicReflectionScene()), "");
  Scene fresnel = makeDynamicReflectionScene();
  fresnel.objects[static_cast<size_t>(fresnel.reflectorIndex())].fresnel = true;
  EXPECT_EQ(CourseFrame::whyNot(fresnel), "a mirror uses Fresnel or roughness");
  Scene glass = makeDynamicReflectionScene();
  glass.objects[static_cast<size_t>(glass.reflectorIndex())].material = Material::Glass;
  EXPECT_EQ(CourseFrame::whyNot(glass), "not every reflector is a live-probe mirror");
  Scene two = makeDynamicReflectionScene();
  two.objects.push_back(two.objects[static_cast<size_t>(two.reflectorIndex())]);
  EXPECT_EQ(CourseFrame::whyNot(two), "the scene has 2 mirrors, not one");
  Scene sky = makeDynamicReflectionScene();
  sky.skybox.cross = "sky.png";
  EXPECT_EQ(CourseFrame::whyNot(sky), "the scene has a skybox");
}

}  // namespace
}  // namespace reflect
