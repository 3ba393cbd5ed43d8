// The accuracy modes against the ray-traced reference on the default scene, and the sweep's
// output formats.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "../gl/gl_fixture.h"
#include "bench/accuracy.h"
#include "bench/sweep.h"
#include "core/presets.h"
#include "core/settings_schema.h"

namespace reflect {
namespace {

AccuracyReport measure(const AccuracySettings& settings, double t,
                       const PlannerSettings& planner = {}) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
  demo->setPlannerSettings(planner);
  EXPECT_EQ(demo->setAccuracySettings(settings), "");
  auto report = measureAccuracy(*demo, t, 384, 384);
  EXPECT_TRUE(report) << report.error();
  return report ? report.value() : AccuracyReport{};
}

TEST(AccuracyModes, DistanceCorrectionLowersTheErrorOnTheDefaultScene) {
  AccuracySettings plain;
  plain.search = Search::Plain;
  AccuracySettings corrected;
  corrected.search = Search::Hierarchical;
  for (double t : {0.0, 2.0, 4.0}) {
    const AccuracyReport a = measure(plain, t);
    const AccuracyReport b = measure(corrected, t);
    std::printf("t=%.0f: plain %.2f dB %.3f deg, corrected %.2f dB %.3f deg\n", t,
                a.reflector.psnrDb, a.meanAngularErrorDeg, b.reflector.psnrDb,
                b.meanAngularErrorDeg);
    EXPECT_GT(b.reflector.psnrDb, a.reflector.psnrDb + 2.0) << "t=" << t;
    EXPECT_LT(b.reflector.rmse, a.reflector.rmse) << "t=" << t;
    // The target: under a quarter of the plain lookup's mean angular error.
    EXPECT_LT(b.meanAngularErrorDeg, 0.25 * a.meanAngularErrorDeg) << "t=" << t;
  }
}

// Issue 5's accuracy target (6 dB) is far exceeded: the shipped default traces the default
// scene's mirror. Held here is the margin reached over the course (the `course` preset's planner
// and accuracy: captured at the origin, plain lookup, 16-bit depth), with the squared error pooled
// over t = 0, 2, 4 s as the sweep pools it: measured +24.55 dB (the course 24.73, 32.39 and
// 26.80 dB at those times; the traced default 91.92, 46.74 and 99 dB: its error at t = 2 s is
// nearly all of its pooled error, and that is one reflector pixel off by 113 levels, `reflect
// bench --sweep --only default --times 0,2,4 --size 384x384`), held 0.25 dB under. (Its time
// budget, 1.5x, is a benchmark: `reflect bench --sweep`.)
constexpr double kDefaultOverCourseDb = 24.3;

TEST(AccuracyModes, TheDefaultIsTwentyFourDecibelsAboveTheCourse) {
  const Preset* course = findPreset("course");
  ASSERT_NE(course, nullptr);
  double courseSquares = 0, defaultSquares = 0;
  for (double t : {0.0, 2.0, 4.0}) {
    const double c = measure(course->accuracy, t, course->planner).reflector.rmse;
    const double shipped = measure(AccuracySettings{}, t).reflector.rmse;
    std::printf("t=%.0f: the course's RMSE %.4f, the default's %.6f\n", t, c, shipped);
    courseSquares += c * c;
    defaultSquares += shipped * shipped;
  }
  ASSERT_GT(defaultSquares, 0.0);  // the traced mirror is not the reference to the bit
  const double gainDb = 10.0 * std::log10(courseSquares / defaultSquares);
  std::printf("default over the course: %+.2f dB\n", gainDb);
  EXPECT_GE(gainDb, kDefaultOverCourseDb);
}

TEST(AccuracyModes, TheCoursesCapturePointIsWorseThanTheReflectorsCentre) {
  AccuracySettings origin;
  origin.search = Search::Plain;
  origin.captureAtOrigin = true;
  AccuracySettings centre = origin;
  centre.captureAtOrigin = false;
  EXPECT_GT(measure(origin, 0.0).meanAngularErrorDeg, measure(centre, 0.0).meanAngularErrorDeg);
}

TEST(Sweep, CsvAndSvgAreWellFormed) {
  SweepRow original;
  original.setting = {"original", {}, 256};
  original.setting.accuracy.captureAtOrigin = true;
  original.medianMs = 10;
  original.psnrDb = 27;
  SweepRow fast = original;
  fast.setting.name = "default";
  fast.medianMs = 8;
  fast.psnrDb = 31;
  fast.pareto = true;
  const std::string csv = sweepCsv({original, fast});
  std::istringstream lines(csv);
  std::string header, line;
  std::getline(lines, header);
  EXPECT_EQ(header.rfind("name,setting,settings,face_size,ms,", 0), 0u);
  for (const char* column : {"ms", "psnr_db", "rmse", "p95"}) {
    EXPECT_NE(("," + header + ",").find(std::string(",") + column + ","), std::string::npos)
        << column;
  }
  int rows = 0;
  while (std::getline(lines, line)) {
    ++rows;
    // The quoted setting holds commas: count the fields outside quotes.
    int fields = 1;
    bool quoted = false;
    for (char c : line) {
      if (c == '"') quoted = !quoted;
      if (c == ',' && !quoted) ++fields;
    }
    int headerFields = 1;
    for (char c : header) headerFields += c == ',';
    EXPECT_EQ(fields, headerFields) << line;
  }
  EXPECT_EQ(rows, 2);
  // The settings column is the settings by the schema's names, as JSON the page applies.
  const size_t start = csv.find("\"{", csv.find("\noriginal,")), end = csv.find("}\"", start);
  std::string json = csv.substr(start + 1, end - start);
  for (size_t q = json.find("\"\""); q != std::string::npos; q = json.find("\"\"", q + 1)) {
    json.erase(q, 1);
  }
  AccuracySettings back;
  EXPECT_EQ(applySettingsJson(nlohmann::json::parse(json), accuracyFields(), back), "");
  EXPECT_TRUE(back == original.setting.accuracy) << json;
  EXPECT_NE(csv.find("\noriginal,"), std::string::npos);
  EXPECT_NE(csv.find("\ndefault,"), std::string::npos);
  const std::string svg = sweepSvg({original, fast});
  EXPECT_EQ(svg.rfind("<svg ", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("<polyline"), std::string::npos);  // the Pareto front
}

TEST(Sweep, SettingsIncludeTheOriginalAndTheShippedDefault) {
  const std::vector<SweepSetting> settings = sweepSettings();
  ASSERT_GE(settings.size(), 10u);
  EXPECT_EQ(settings[0].name, "original");
  // The course's row is the `course` preset, planner and accuracy: one definition of the course.
  const Preset* course = findPreset("course");
  ASSERT_NE(course, nullptr);
  EXPECT_TRUE(settings[0].accuracy == course->accuracy);
  EXPECT_EQ(settings[0].planner.policy, course->planner.policy);
  EXPECT_EQ(settings[0].planner.captureLod, course->planner.captureLod);
  EXPECT_EQ(settings[0].planner.viewLod, course->planner.viewLod);
  EXPECT_TRUE(settings[0].accuracy.captureAtOrigin);
  EXPECT_EQ(settings[0].accuracy.search, Search::Plain);
  // Every other row recaptures every face every frame, its capture cost counted in full.
  for (size_t i = 1; i < settings.size(); ++i) {
    EXPECT_EQ(settings[i].planner.policy, UpdatePolicy::EveryFrame) << settings[i].name;
  }
  EXPECT_EQ(settings[1].name, "default");
  EXPECT_TRUE(settings[1].accuracy == AccuracySettings{});  // what Demo ships with
  EXPECT_EQ(settings[1].faceSize, 256);
}

}  // namespace
}  // namespace reflect
