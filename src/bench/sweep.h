// `reflect bench --sweep`: every accuracy setting rendered at fixed times, timed (median frame
// ms, interleaved with the others so machine noise hits them alike) and compared with the
// ray-traced reference; written as a table, a CSV and an SVG plot of error against time with
// the Pareto front marked.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/demo.h"
#include "core/accuracy_settings.h"
#include "core/result.h"

namespace reflect {

struct SweepSetting {
  std::string name;  // "original", "default", "size-64", "distance-4", ...
  AccuracySettings accuracy;
  int faceSize = 256;
};

// The settings the sweep measures: the course's ("original"), the shipped default ("default")
// and one knob at a time around them.
std::vector<SweepSetting> sweepSettings();

struct SweepRow {
  SweepSetting setting;
  double medianMs = 0, p10Ms = 0, p90Ms = 0;
  double psnrDb = 0, rmse = 0, p95 = 0, maxError = 0, meanAngularErrorDeg = 0;
  double offReflectorPsnrDb = 0;
  bool pareto = false;  // no other setting is both faster and more accurate
};

struct SweepOptions {
  int width = 512;
  int height = 512;
  int frames = 30;                              // timed frames per setting (every-frame policy)
  std::vector<double> times = {0.0, 2.0, 4.0};  // error measured at these scene times
};

using SweepDemoFactory = std::function<Result<std::unique_ptr<Demo>>()>;

Result<std::vector<SweepRow>> runSweep(const SweepDemoFactory& makeDemo,
                                       const std::vector<SweepSetting>& settings,
                                       const SweepOptions& options);

std::string sweepTable(const std::vector<SweepRow>& rows);
std::string sweepCsv(const std::vector<SweepRow>& rows);
std::string sweepSvg(const std::vector<SweepRow>& rows);

}  // namespace reflect
