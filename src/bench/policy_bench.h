// `reflect bench`: the update policies compared on one scene in one run. Timing runs the
// policies' demos interleaved frame by frame (so machine noise hits them alike); accuracy renders
// each policy in lockstep with the every-frame policy and compares the pictures.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/demo.h"
#include "core/frame_planner.h"
#include "core/result.h"

namespace reflect {

struct PolicyCase {
  std::string label;
  PlannerSettings settings;
  bool reflectorAsPhong = false;  // the reference for the static-scene target
};

struct PolicyBenchOptions {
  int width = 800;
  int height = 800;
  int warmup = 10;
  int frames = 120;
  int accuracyFrames = 60;
  double dtSeconds = 1.0 / 60.0;  // 0 = a static scene (nothing moves)
};

struct PolicyResult {
  std::string label;
  double medianMs = 0, p10Ms = 0, p90Ms = 0, captureMedianMs = 0;
  double facesPerFrame = 0, captureDrawsPerFrame = 0, captureTrianglesPerFrame = 0,
         trianglesPerFrame = 0;
  int maxStalenessFrames = 0;
  int maxDifference = 0;       // largest channel difference from every-frame, 0..255 (-1: n/a)
  double differingPixels = 0;  // fraction of pixels that differ at all (worst frame)
};

using DemoFactory = std::function<Result<std::unique_ptr<Demo>>(bool reflectorAsPhong)>;

Result<std::vector<PolicyResult>> benchPolicies(const DemoFactory& makeDemo,
                                                const std::vector<PolicyCase>& cases,
                                                const PolicyBenchOptions& options);

std::string formatPolicyTable(const std::vector<PolicyResult>& results);

}  // namespace reflect
