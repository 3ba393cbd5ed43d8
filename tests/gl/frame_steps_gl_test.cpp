// Step through a frame on a real frame: `render --steps` writes one PNG per step of the frame's
// step list, the last is the normal frame pixel for pixel, a capture step's image holds the face
// it drew as the probe keeps it, and the step callback can stop the capture where it likes.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "app/frame_step_files.h"
#include "app/frame_step_view.h"
#include "app/headless_frames.h"
#include "core/scene.h"
#include "gfx/cube_readback.h"
#include "gfx/offscreen_target.h"
#include "gl_fixture.h"

namespace reflect {
namespace {

constexpr int kSize = 400;  // room under the title for a 256-texel face, unshrunk

std::string freshFolder(const std::string& name) {
  const std::string dir = std::string(OUTPUT_DIR) + "/" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

size_t pngsIn(const std::string& dir) {
  size_t count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    count += entry.path().extension() == ".png" ? 1 : 0;
  }
  return count;
}

// What the plan draws, counted from the plan: a pass a face (three with two layers), a pyramid
// per probe with depths (every probe here: the hierarchical search), the main pass.
size_t planDraws(const FramePlan& plan) {
  size_t draws = 1;
  for (const ProbePlan& probe : plan.probes) {
    for (const FacePlan& face : probe.faces) draws += face.layers == 2 ? 3 : 1;
    if (!probe.faces.empty() && !probe.plainLookupSuffices) ++draws;
  }
  return draws;
}

TEST(FrameStepsGl, OnePngPerStepAndTheLastIsTheNormalFrame) {
  auto normal = testing::makeCapturingDemo(makeDynamicReflectionScene());
  const Result<RgbaImage> expected = renderFrameAt(*normal, 0.5, kSize, kSize);
  ASSERT_TRUE(expected) << expected.error();

  auto stepped = testing::makeCapturingDemo(makeDynamicReflectionScene());
  const std::string dir = freshFolder("frame_steps");
  std::vector<std::string> lines;
  const Result<RgbaImage> frame = renderFrameInSteps(*stepped, 0.5, kSize, kSize, dir, lines);
  ASSERT_TRUE(frame) << frame.error();
  const std::vector<FrameStep> steps = stepped->lastSteps();
  EXPECT_EQ(steps.size(), planDraws(stepped->lastPlan()));
  EXPECT_GE(steps.size(), 8u);  // the first frame: six faces, a pyramid, the main pass at least
  EXPECT_EQ(pngsIn(dir), steps.size());
  EXPECT_EQ(lines.size(), steps.size());
  EXPECT_EQ(lines.back(), "step " + std::to_string(steps.size()) + " of " +
                              std::to_string(steps.size()) + ": " + steps.back().label);
  // Stepping changes nothing of the frame: its last step is the normal frame.
  const Result<RgbaImage> last = readPng(
      stepFileName(dir, static_cast<int>(steps.size()) - 1, static_cast<int>(steps.size())));
  ASSERT_TRUE(last) << last.error();
  EXPECT_EQ(last.value().pixels, expected.value().pixels);
  EXPECT_EQ(frame.value().pixels, expected.value().pixels);
  // The main step's triangles are the ones the main pass drew.
  EXPECT_EQ(steps.back().triangles, stepped->lastStats().mainTriangles);
}

TEST(FrameStepsGl, ACaptureStepShowsTheFaceItDrew) {
  auto demo = testing::makeCapturingDemo(makeDynamicReflectionScene());
  const std::string dir = freshFolder("frame_steps_face");
  std::vector<std::string> lines;
  ASSERT_TRUE(renderFrameInSteps(*demo, 0.0, kSize, kSize, dir, lines));
  const std::vector<FrameStep> steps = demo->lastSteps();
  ASSERT_EQ(steps.front().pass, StepPass::Colour);
  // Pass 1 writes the face's first colour layer, which nothing later in the frame touches.
  const Result<CubeFaces> faces =
      readCubeFaces(*demo->renderer()->probeTarget(steps.front().reflector), FacesChannel::Colour);
  ASSERT_TRUE(faces) << faces.error();
  const RgbaImage& face = faces.value()[static_cast<size_t>(steps.front().face)];
  const Result<RgbaImage> image = readPng(stepFileName(dir, 0, static_cast<int>(steps.size())));
  ASSERT_TRUE(image) << image.error();
  // Centred across; below the title: find the face's first row, then every row must follow it.
  const int left = (kSize - face.width) / 2;
  const size_t rowBytes = static_cast<size_t>(face.width) * 4;
  int top = -1;
  for (int y = 0; y + face.height <= kSize && top < 0; ++y) {
    if (std::memcmp(image.value().at(left, y), face.at(0, 0), rowBytes) == 0) top = y;
  }
  ASSERT_GE(top, 0) << "the face is not in the step's image";
  for (int y = 0; y < face.height; ++y) {
    ASSERT_EQ(std::memcmp(image.value().at(left, top + y), face.at(0, y), rowBytes), 0) << y;
  }
}

TEST(FrameStepsGl, TheCallbackStopsTheCaptureAfterTheStepItRefuses) {
  auto demo = testing::makeCapturingDemo(makeDynamicReflectionScene());
  std::vector<int> told;
  demo->setStepCallback([&](const FrameStep&, int index, int) {
    told.push_back(index);
    return index < 2;
  });
  ASSERT_TRUE(renderFrameAt(*demo, 0.0, 64, 64));
  EXPECT_EQ(told, (std::vector<int>{0, 1, 2}));
  // Less was drawn than the plan's captures.
  demo->setStepCallback(nullptr);
  auto whole = testing::makeCapturingDemo(makeDynamicReflectionScene());
  ASSERT_TRUE(renderFrameAt(*whole, 0.0, 64, 64));
  EXPECT_LT(demo->lastStats().captureTriangles, whole->lastStats().captureTriangles);
}

TEST(FrameStepsGl, ThePagesStepsAreTheCommandLinesAndItsLastIsTheFrame) {
  auto cli = testing::makeCapturingDemo(makeDynamicReflectionScene());
  const std::string dir = freshFolder("frame_steps_page");
  std::vector<std::string> lines;
  const Result<RgbaImage> frame = renderFrameInSteps(*cli, 0.5, kSize, kSize, dir, lines);
  ASSERT_TRUE(frame) << frame.error();

  // The page: frames drawn, then paused (a frame that captures nothing), then stepped.
  auto page = testing::makeCapturingDemo(makeDynamicReflectionScene());
  auto screen = OffscreenTarget::create(kSize, kSize);
  ASSERT_TRUE(screen);
  page->clock().set(0.5);
  page->frame(0.0, screen.value().framebuffer(), kSize, kSize, true);
  page->frame(0.0, screen.value().framebuffer(), kSize, kSize, true);
  ASSERT_EQ(page->lastPlan().facesCaptured(), 0);
  const FramePlan pausedPlan = page->lastPlan();
  Result<std::vector<FrameStep>> steps =
      page->drawFrameStep(0, screen.value().framebuffer(), kSize, kSize);
  ASSERT_TRUE(steps) << steps.error();
  const int count = static_cast<int>(steps.value().size());
  ASSERT_EQ(static_cast<size_t>(count), lines.size());
  for (int i = 0; i < count; ++i) {
    EXPECT_EQ(stepTitle(steps.value()[static_cast<size_t>(i)], i, count),
              lines[static_cast<size_t>(i)]);
  }
  // Step 1 on the screen is step-01.png; the last step is the frame.
  const Result<RgbaImage> first = readPng(stepFileName(dir, 0, count));
  ASSERT_TRUE(first) << first.error();
  EXPECT_EQ(screen.value().readPixels().pixels, first.value().pixels);
  ASSERT_TRUE(page->drawFrameStep(count - 1, screen.value().framebuffer(), kSize, kSize));
  EXPECT_EQ(screen.value().readPixels().pixels, frame.value().pixels);
  // Past the end is the end; the demo's own plan is untouched.
  ASSERT_TRUE(page->drawFrameStep(count + 5, screen.value().framebuffer(), kSize, kSize));
  EXPECT_EQ(screen.value().readPixels().pixels, frame.value().pixels);
  EXPECT_EQ(page->lastPlan().facesCaptured(), pausedPlan.facesCaptured());
}

TEST(FrameStepsGl, AFolderThatIsNotThereIsAnError) {
  auto demo = testing::makeCapturingDemo(makeDynamicReflectionScene());
  std::vector<std::string> lines;
  const Result<RgbaImage> frame =
      renderFrameInSteps(*demo, 0.0, 64, 64, "/nonexistent/steps", lines);
  ASSERT_FALSE(frame);
  EXPECT_EQ(frame.error(), "/nonexistent/steps is not a folder");
  EXPECT_TRUE(lines.empty());
}

}  // namespace
}  // namespace reflect
