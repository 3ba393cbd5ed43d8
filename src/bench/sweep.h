// `reflect bench --sweep`: every accuracy setting rendered at fixed times, timed (median frame
// ms and CPU ms, interleaved with the others so machine noise hits them alike) and compared with
// the ray-traced reference; written as a table, a CSV and an SVG plot of error against time with
// the Pareto front marked. The constants of the lookup were chosen on the tuning times; the
// table reports the held-out times, which played no part in that choice.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/demo.h"
#include "core/accuracy_settings.h"
#include "core/frame_planner.h"
#include "core/result.h"
#include "reference/reference_renderer.h"

namespace reflect {

// The default planner with every face recaptured every frame, so that each row's capture cost
// is counted in full.
inline PlannerSettings everyFramePlanner() {
  PlannerSettings planner;
  planner.policy = UpdatePolicy::EveryFrame;
  return planner;
}

struct SweepSetting {
  std::string name;  // "original", "default", "size-64", "distance-4", ...
  AccuracySettings accuracy;
  int faceSize = 256;  // 0: the scene's own
  PlannerSettings planner = everyFramePlanner();
};

// The settings the sweep measures: the course's ("original": the `course` preset's planner and
// accuracy, core/presets.h), the shipped default ("default") and one knob at a time around
// them.
std::vector<SweepSetting> sweepSettings();

struct SweepRow {
  SweepSetting setting;
  double medianMs = 0, p10Ms = 0, p90Ms = 0;
  double cpuMs = 0;  // median CPU time of the process per frame
  // Medians: the capture (faces and prefilter) and its prefilter pass alone (rough readers).
  double captureMs = 0, filterMs = 0, irradianceMs = 0;
  // Rough mirrors: per reflector of roughness > 0, "roughness R" and its pooled PSNR (held-out
  // times), in scene order.
  std::vector<std::pair<std::string, double>> roughPsnrDb;
  // Over the reflector at the held-out times: PSNR of the pooled error, the worst time's PSNR,
  // pixels off by more than kVisibleErrorLevels per frame (mean and worst time), RMSE, mean p95,
  // largest error, mean angular error of the looked-up direction; off the reflector, PSNR.
  double psnrDb = 0, worstPsnrDb = 0, visiblePerFrame = 0, worstVisible = 0, rmse = 0, p95 = 0,
         maxError = 0, meanAngularErrorDeg = 0;
  double offReflectorPsnrDb = 0;
  double tunedPsnrDb = 0;  // the same pooled PSNR at the tuning times
  bool pareto = false;     // no other setting is both faster and more accurate
};

struct SweepOptions {
  int width = 512;
  int height = 512;
  int frames = 30;  // timed frames per setting (every-frame policy)
  // The lookup's constants were chosen at these times...
  std::vector<double> tunedTimes = {0, 1, 2, 3, 4, 5, 6, 7};
  // ...and the table reports these.
  std::vector<double> heldOutTimes = {0.5, 1.5, 2.5, 3.5, 4.5, 5.5, 6.5, 7.5};
  ReferenceOptions reference;  // the references' Monte Carlo (rough mirrors' lobe samples)
};

using SweepDemoFactory = std::function<Result<std::unique_ptr<Demo>>()>;

Result<std::vector<SweepRow>> runSweep(const SweepDemoFactory& makeDemo,
                                       const std::vector<SweepSetting>& settings,
                                       const SweepOptions& options);

std::string sweepTable(const std::vector<SweepRow>& rows);
std::string sweepCsv(const std::vector<SweepRow>& rows);
std::string sweepSvg(const std::vector<SweepRow>& rows);

}  // namespace reflect
