// The faces view of a real frame: its squares are the probe's faces as read back, its marks follow
// what the frame redrew, a frame with no probe says why instead of showing stale pixels, and with
// the view on the screen shows the view (with it off, the frame's own picture: the goldens).
#include <gtest/gtest.h>

#include <cstring>

#include "app/faces_view.h"
#include "core/irradiance.h"
#include "core/scene.h"
#include "gfx/cube_readback.h"
#include "gfx/offscreen_target.h"
#include "gl_fixture.h"
#include "platform/native/model_paths.h"

namespace reflect {
namespace {

TEST(FacesView, TheSquaresAreTheProbesFacesAndTheMarksFollowTheFrames) {
  auto demo = testing::makeCapturingDemo(makeDynamicReflectionScene());
  auto screen = OffscreenTarget::create(64, 64);
  ASSERT_TRUE(screen);
  demo->frame(0.0, screen.value().framebuffer(), 64, 64, true);
  const int reflector = demo->scene().reflectorIndex();
  const CubeCaptureTarget* probe = demo->renderer()->probeTarget(reflector);
  ASSERT_NE(probe, nullptr);
  Result<RgbaImage> view = composeFacesView(*demo->renderer(), demo->scene(), demo->lastPlan(),
                                            demo->insideViews().ages(), FacesChannel::Colour);
  ASSERT_TRUE(view) << view.error();
  testing::saveOutput(view.value(), "faces_view_colour.png");
  const Result<CubeFaces> faces = readCubeFaces(*probe, FacesChannel::Colour);
  ASSERT_TRUE(faces) << faces.error();
  const CrossGeometry g = crossGeometry(probe->faceSize());
  for (size_t f = 0; f < 6; ++f) {
    for (int y = 0; y < probe->faceSize(); ++y) {
      ASSERT_EQ(std::memcmp(view.value().at(g.squareOrigin[f][0], g.squareOrigin[f][1] + y),
                            faces.value()[f].at(0, y), static_cast<size_t>(probe->faceSize()) * 4),
                0)
          << "face " << f << " row " << y;
    }
  }
  // The first frame drew all six; a frame later with nothing moved (no time passed), the
  // when-changed policy redraws none, and each face is a frame old.
  for (const FaceMark& mark : demo->insideViews().ages().marks(reflector)) {
    EXPECT_EQ(faceStatus(mark), "CAPTURED");
  }
  demo->frame(0.0, screen.value().framebuffer(), 64, 64, true);
  ASSERT_EQ(demo->lastPlan().facesCaptured(), 0);
  for (const FaceMark& mark : demo->insideViews().ages().marks(reflector)) {
    EXPECT_EQ(faceStatus(mark), "STALE 1 FRAME");
  }
}

TEST(FacesView, TheProbeSettingPicksWhichOfTheFramesProbesIsShown) {
  Result<Scene> scene = loadNamedScene("two-mirrors");
  ASSERT_TRUE(scene) << scene.error();
  auto demo = testing::makeCapturingDemo(scene.take());
  auto screen = OffscreenTarget::create(64, 64);
  ASSERT_TRUE(screen);
  demo->frame(0.0, screen.value().framebuffer(), 64, 64, true);
  const FramePlan& plan = demo->lastPlan();
  ASSERT_EQ(plan.probes.size(), 2u);
  EXPECT_EQ(shownProbe(plan, 1), &plan.probes[0]);
  EXPECT_EQ(shownProbe(plan, 2), &plan.probes[1]);
  EXPECT_EQ(shownProbe(plan, 9), &plan.probes[1]);  // past the last: the last
  EXPECT_EQ(shownProbe(FramePlan{}, 1), nullptr);
  // The second probe's cross holds the second probe's faces, which are not the first's.
  const Result<RgbaImage> view =
      composeFacesView(*demo->renderer(), demo->scene(), plan, demo->insideViews().ages(),
                       FacesChannel::Colour, 0, 0, 2);
  ASSERT_TRUE(view) << view.error();
  const CubeCaptureTarget* second = demo->renderer()->probeTarget(plan.probes[1].reflector);
  const CubeCaptureTarget* first = demo->renderer()->probeTarget(plan.probes[0].reflector);
  ASSERT_TRUE(second && first);
  const Result<CubeFaces> faces = readCubeFaces(*second, FacesChannel::Colour);
  const Result<CubeFaces> others = readCubeFaces(*first, FacesChannel::Colour);
  ASSERT_TRUE(faces && others);
  ASSERT_NE(faces.value()[0].pixels, others.value()[0].pixels);
  const CrossGeometry g = crossGeometry(second->faceSize());
  for (int y = 0; y < second->faceSize(); ++y) {
    ASSERT_EQ(std::memcmp(view.value().at(g.squareOrigin[0][0], g.squareOrigin[0][1] + y),
                          faces.value()[0].at(0, y), static_cast<size_t>(second->faceSize()) * 4),
              0)
        << "row " << y;
  }
}

TEST(FacesView, AFrameWithNoProbeSaysWhyAndTheScreenShowsIt) {
  // The default traces the sphere's rays in this small view: no cube map exists.
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  auto screen = OffscreenTarget::create(64, 64);
  ASSERT_TRUE(screen);
  demo->frame(0.0, screen.value().framebuffer(), 64, 64, true);
  ASSERT_TRUE(demo->lastPlan().probes.empty());
  const Result<RgbaImage> view =
      composeFacesView(*demo->renderer(), demo->scene(), demo->lastPlan(),
                       demo->insideViews().ages(), FacesChannel::Colour);
  ASSERT_FALSE(view);
  EXPECT_NE(view.error().find("no cube map this frame"), std::string::npos) << view.error();
  // With the view on, the screen is the message image, pixel for pixel.
  demo->setInsideView(InsideView::Faces, FacesChannel::Colour);
  demo->frame(0.0, screen.value().framebuffer(), 64, 64, true);
  EXPECT_EQ(screen.value().readPixels().pixels, messageImage(view.error(), 64, 64).pixels);
}

TEST(FacesView, WithTheViewOnTheScreenIsTheCrossCentred) {
  auto demo = testing::makeCapturingDemo(makeDynamicReflectionScene());
  demo->setInsideView(InsideView::Faces, FacesChannel::Distance);
  // The cross of a 256 face is 4 x 282 = 1128 wide: a screen that holds it with room around.
  const int width = 1200, height = 1000;
  auto screen = OffscreenTarget::create(width, height);
  ASSERT_TRUE(screen);
  demo->frame(0.0, screen.value().framebuffer(), width, height, true);
  const Result<RgbaImage> view =
      composeFacesView(*demo->renderer(), demo->scene(), demo->lastPlan(),
                       demo->insideViews().ages(), FacesChannel::Distance);
  ASSERT_TRUE(view) << view.error();
  testing::saveOutput(view.value(), "faces_view_distance.png");
  const RgbaImage shown = screen.value().readPixels();
  const int left = (width - view.value().width) / 2;
  // The framebuffer's origin is its bottom row: the image's top sits (height - h) - origin.y rows
  // below the screen's top, with origin.y = (height - h) / 2.
  const int top = height - view.value().height - (height - view.value().height) / 2;
  for (int y = 0; y < view.value().height; y += 7) {
    ASSERT_EQ(std::memcmp(shown.at(left, top + y), view.value().at(0, y),
                          static_cast<size_t>(view.value().width) * 4),
              0)
        << "row " << y;
  }
}

// probe-lit: the view steps to mario's own probe (the frame's probes in order), and the
// irradiance channel shows what that figure takes from it: its colour faces projected on the
// order-2 harmonics and evaluated at each texel's direction (core/irradiance.h, whose test holds
// the numbers), the title naming the channel.
TEST(FacesView, TheIrradianceChannelShowsTheLightAProbeLitFigureTakes) {
  Result<Scene> scene = loadNamedScene("probe-lit");
  ASSERT_TRUE(scene) << scene.error();
  auto demo = testing::makeDemo(scene.take());
  auto screen = OffscreenTarget::create(64, 64);
  ASSERT_TRUE(screen);
  demo->frame(1.0, screen.value().framebuffer(), 64, 64, true);
  const FramePlan& plan = demo->lastPlan();
  constexpr int kMario = 2;
  int shown = 0;
  for (size_t i = 0; i < plan.probes.size(); ++i) {
    if (plan.probes[i].reflector == kMario) shown = static_cast<int>(i) + 1;
  }
  ASSERT_GT(shown, 0) << "mario's own probe is not in the plan";
  const Result<RgbaImage> view =
      composeFacesView(*demo->renderer(), demo->scene(), plan, demo->insideViews().ages(),
                       FacesChannel::Irradiance, 0, 0, shown);
  ASSERT_TRUE(view) << view.error();
  testing::saveOutput(view.value(), "faces_view_irradiance.png");
  const CubeCaptureTarget* probe = demo->renderer()->probeTarget(kMario);
  ASSERT_NE(probe, nullptr);
  ASSERT_EQ(probe->faceSize(), kIrradianceFaceSize);
  const Result<CubeFaces> colours = readCubeFaces(*probe, FacesChannel::Colour);
  const Result<CubeFaces> light = readCubeFaces(*probe, FacesChannel::Irradiance);
  ASSERT_TRUE(colours && light);
  const CubeFaces expected = irradianceCube(projectIrradiance(colours.value()), probe->faceSize());
  const CrossGeometry g = crossGeometry(probe->faceSize());
  for (size_t f = 0; f < 6; ++f) {
    ASSERT_EQ(light.value()[f].pixels, expected[f].pixels) << "face " << f;
    ASSERT_NE(light.value()[f].pixels, colours.value()[f].pixels) << "face " << f;
    for (int y = 0; y < probe->faceSize(); ++y) {
      ASSERT_EQ(std::memcmp(view.value().at(g.squareOrigin[f][0], g.squareOrigin[f][1] + y),
                            expected[f].at(0, y), static_cast<size_t>(probe->faceSize()) * 4),
                0)
          << "face " << f << " row " << y;
    }
  }
}

}  // namespace
}  // namespace reflect
