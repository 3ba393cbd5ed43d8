// The accuracy modes against the ray-traced reference on the default scene, and the sweep's
// output formats.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "../gl/gl_fixture.h"
#include "bench/accuracy.h"
#include "bench/sweep.h"

namespace reflect {
namespace {

AccuracyReport measure(const AccuracySettings& settings, double t) {
  auto demo = testing::makeDemo(makeDynamicReflectionScene());
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

// Issue 5's accuracy target, held as a regression check: the shipped default is at least 6 dB
// above the course's setting (captured at the origin, plain lookup, 16-bit depth), with the
// squared error pooled over t = 0, 2, 4 s as the sweep pools it. (Its time budget, 1.5x, is a
// benchmark: `reflect bench --sweep`.)
TEST(AccuracyModes, TheDefaultIsSixDecibelsAboveTheCourse) {
  const std::vector<SweepSetting> settings = sweepSettings();
  double courseSquares = 0, defaultSquares = 0;
  for (double t : {0.0, 2.0, 4.0}) {
    const double course = measure(settings[0].accuracy, t).reflector.rmse;
    const double shipped = measure(settings[1].accuracy, t).reflector.rmse;
    courseSquares += course * course;
    defaultSquares += shipped * shipped;
  }
  const double gainDb = 10.0 * std::log10(courseSquares / defaultSquares);
  std::printf("default over the course: %+.2f dB\n", gainDb);
  EXPECT_GE(gainDb, 6.0);
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
  EXPECT_TRUE(settings[0].accuracy.captureAtOrigin);
  EXPECT_EQ(settings[0].accuracy.search, Search::Plain);
  EXPECT_EQ(settings[1].name, "default");
  EXPECT_TRUE(settings[1].accuracy == AccuracySettings{});  // what Demo ships with
  EXPECT_EQ(settings[1].faceSize, 256);
}

}  // namespace
}  // namespace reflect
