// Every shipped scene's accuracy, held about 1 dB under what README's table measured
// (tools/scene_accuracy.sh: 400x400, the held-out times t = 0.5, 2.5, 4.5, 6.5 s, against the
// Embree reference), for the default (search: planned) and the cube-map search (hierarchical):
// the pooled PSNR and the worst time's at most 1 dB lower, and the pixels off by more than 32
// levels at most 10% (and one pixel) more. When a change raises a figure, raise its floor here in
// the same commit; when one falls, say why in that commit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "app/headless_frames.h"
#include "bench/accuracy.h"
#include "core/presets.h"
#include "gl_fixture.h"
#include "platform/native/model_paths.h"

namespace reflect {
namespace {

constexpr int kSize = 400;
const std::vector<double> kHeldOutTimes = {0.5, 2.5, 4.5, 6.5};
constexpr double kMarginDb = 1.0;

struct Row {
  double meanDb, worstDb, visible;  // as measured: pooled PSNR, worst time, pixels > 32 a frame
};
struct SceneRows {
  std::string scene;
  Row planned, hierarchical;
};

// docs/bench/scene-accuracy.txt
const std::vector<SceneRows> kRows = {
    {"ex12-1", {42.42, 39.61, 12.8}, {42.42, 39.61, 12.8}},
    {"ex12-2", {92.25, 92.18, 0.0}, {39.08, 38.26, 20.2}},
    {"ex12-2-fresnel", {86.51, 86.16, 0.0}, {50.01, 44.80, 1.8}},
    {"glass-sphere", {95.28, 89.26, 0.0}, {28.53, 22.77, 182.0}},
    {"shared-probe", {88.03, 85.03, 0.0}, {22.45, 22.23, 514.0}},
    {"skybox", {22.17, 21.30, 2715.8}, {22.14, 21.28, 2748.0}},
    {"skybox-grid", {70.03, 70.01, 0.0}, {37.57, 31.87, 26.0}},
    {"two-mirrors", {87.96, 86.28, 0.0}, {33.54, 31.25, 112.2}},
};

// The pooled PSNR over the held-out times, the worst time's and the pixels off by more than 32
// levels a frame, as measured.
Row measureHeldOut(const std::string& sceneName, const PlannerSettings& planner,
                   const AccuracySettings& accuracy) {
  Result<Scene> scene = loadNamedScene(sceneName);
  EXPECT_TRUE(scene) << scene.error();
  if (!scene) return {0.0, 0.0, INFINITY};
  auto demo = testing::makeDemo(scene.take());
  demo->setPlannerSettings(planner);
  EXPECT_EQ(demo->setAccuracySettings(accuracy), "");
  double squared = 0.0, worst = INFINITY, visible = 0.0;
  for (double t : kHeldOutTimes) {
    // A frame at t first: a mirror seen in another shows that one's cube from the frame before
    // (one bounce, a frame late), which should be of this time, not of the last one measured.
    EXPECT_TRUE(renderFrameAt(*demo, t, kSize, kSize));
    auto report = measureAccuracy(*demo, t, kSize, kSize);
    EXPECT_TRUE(report) << report.error();
    if (!report) return {0.0, 0.0, INFINITY};
    const ImageErrorMetrics& r = report.value().reflector;
    squared += r.rmse * r.rmse;
    worst = std::min(worst, r.psnrDb);
    visible += static_cast<double>(r.visibleErrorPixels);
  }
  const double mean = psnrFromRmse(std::sqrt(squared / static_cast<double>(kHeldOutTimes.size())));
  return {mean, worst, visible / static_cast<double>(kHeldOutTimes.size())};
}

void expectFloors(const std::string& sceneName, Search search, const Row& row) {
  // As the table was measured (the sweep): every face recaptured every frame. (Under
  // when-changed, a mirror seen in another after a jump in time shows that mirror's cube from
  // before the jump: one bounce, a frame late.)
  PlannerSettings everyFrame;
  everyFrame.policy = UpdatePolicy::EveryFrame;
  AccuracySettings settings;
  settings.search = search;
  const Row m = measureHeldOut(sceneName, everyFrame, settings);
  std::printf("%s, %s: %.2f dB (worst %.2f), %.1f pixels > 32 a frame; README %.2f (%.2f), %.1f\n",
              sceneName.c_str(), searchName(search), m.meanDb, m.worstDb, m.visible, row.meanDb,
              row.worstDb, row.visible);
  EXPECT_GE(m.meanDb, row.meanDb - kMarginDb) << sceneName << ", " << searchName(search);
  EXPECT_GE(m.worstDb, row.worstDb - kMarginDb) << sceneName << ", " << searchName(search);
  EXPECT_LE(m.visible, row.visible * 1.1 + 1.0) << sceneName << ", " << searchName(search);
}

// Test names and failures show the scene, not the struct's bytes.
void PrintTo(const SceneRows& rows, std::ostream* out) {
  *out << rows.scene;
}

class AccuracyFloors : public ::testing::TestWithParam<SceneRows> {};

TEST_P(AccuracyFloors, HoldsReadmesRow) {
  const SceneRows& rows = GetParam();
  expectFloors(rows.scene, Search::Planned, rows.planned);
  expectFloors(rows.scene, Search::Hierarchical, rows.hierarchical);
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, AccuracyFloors, ::testing::ValuesIn(kRows),
                         [](const auto& param) {
                           std::string name = param.param.scene;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// The course's path (the `course` preset, planner and accuracy: six faces every frame at full
// detail, captured at the origin, looked up along the ray, 16-bit depth) on the default scene,
// measured as the rows above: held a few tenths of a dB under the level it reaches, and its
// pixels off by more than 32 levels at most a few percent above it. Measured (400x400, t = 0.5,
// 2.5, 4.5, 6.5 s): 25.89 dB pooled, the worst time 24.71 dB, 378 pixels a frame (floors 25.59
// and 24.41 dB, at most 391 pixels).
constexpr Row kCourse = {25.89, 24.71, 378.0};
constexpr double kCourseMarginDb = 0.3;

TEST(CourseAccuracy, HoldsItsFloorsOnTheDefaultScene) {
  const Preset* course = findPreset("course");
  ASSERT_NE(course, nullptr);
  const Row m = measureHeldOut("ex12-2", course->planner, course->accuracy);
  std::printf("ex12-2, the course: %.2f dB (worst %.2f), %.1f pixels > 32 a frame\n", m.meanDb,
              m.worstDb, m.visible);
  EXPECT_GE(m.meanDb, kCourse.meanDb - kCourseMarginDb);
  EXPECT_GE(m.worstDb, kCourse.worstDb - kCourseMarginDb);
  EXPECT_LE(m.visible, kCourse.visible * 1.03 + 2.0);
}

}  // namespace
}  // namespace reflect
