// What `reflect bench` runs, from plain options and a demo factory: the policy comparison (the
// default mode), one policy, the growth table and the accuracy sweep. Each prints its report to
// stdout (README's tables are made from it) and returns "" or the error.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/demo.h"
#include "core/frame_planner.h"
#include "core/result.h"

namespace reflect {

struct BenchCommandOptions {
  std::string scene = "ex12-2";  // printed by the sweep
  std::string assets;            // printed: the folder the models came from ("" = built-in)
  int width = 800;               // frame size (the sweep renders at SweepOptions' own size)
  int height = 800;
  int cubeSize = 256;  // printed
  // Unset: each mode's own default (benchFramesDefault, benchWarmupDefault).
  std::optional<int> frames;
  std::optional<int> warmup;
  int accuracyFrames = 60;        // the policy comparison: frames compared with every-frame
  PlannerSettings planner;        // the single policy; the comparison's time-sliced, every-n, LODs
  std::vector<double> times;      // the sweeps: scene times measured (empty: their own)
  std::vector<std::string> only;  // the sweep: just these settings ("" = all)
  std::optional<glm::ivec2> sweepSize;  // the sweep: the frame size, if not its own
  std::string csv;                      // the sweep: CSV output ("" = none)
  std::string svg;                      // the sweep: SVG plot output ("" = none)
  double budgetMs = 0.0;                // --budget: the frame budget "auto" picks within
  std::optional<int> lobeSamples;       // the sweep: the reference's lobe rays (unset: its own)
};

enum class BenchMode {
  PolicyComparison,
  SinglePolicy,
  Growth,
  Sweep,
  Costs,
  LodSweep,
  ViewLodSweep,
  Budget
};

// Timed frames (per policy, per setting, per cell) and warm-up frames when not given.
int benchFramesDefault(BenchMode mode);
int benchWarmupDefault(BenchMode mode);  // 0 for the sweep, which has none to set

// Which demo a bench asks the factory for.
struct DemoVariant {
  bool reflectorAsPhong = false;  // every material plain Phong (the static-scene reference)
  bool defaultAccuracy = false;   // the shipped accuracy settings (the sweep sets its own)
};
// Makes the demo the command line describes (scene, models, cube size, camera, planner and
// accuracy settings), with its GL resources, in the current context.
using BenchDemoFactory = std::function<Result<std::unique_ptr<Demo>>(const DemoVariant&)>;

// Every policy on the animated scene, then the static scene against a plain-Phong reflector.
std::string runPolicyComparison(const BenchCommandOptions& options,
                                const BenchDemoFactory& makeDemo);
// One policy (options.planner): frames of the animated scene, median and spread.
std::string runSinglePolicy(const BenchCommandOptions& options, const BenchDemoFactory& makeDemo);
// Every accuracy setting against the ray-traced reference: table, CSV, SVG.
std::string runSweepCommand(const BenchCommandOptions& options, const BenchDemoFactory& makeDemo);
// Capture LOD values against full detail (reflector vs the reference, capture triangles, frame
// time), and view LOD values against the full-detail view (bench/lod_sweep.h).
std::string runLodSweepCommand(const BenchCommandOptions& options,
                               const BenchDemoFactory& makeDemo);
std::string runViewLodSweepCommand(const BenchCommandOptions& options,
                                   const BenchDemoFactory& makeDemo);
// Frame time against reflectors and triangles, on scenes generated from `modelDirectory`.
std::string runGrowthCommand(const BenchCommandOptions& options, const std::string& modelDirectory);

}  // namespace reflect
