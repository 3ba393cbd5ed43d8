#include "bench/bench_commands.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "app/headless_frames.h"
#include "bench/growth_bench.h"
#include "bench/lod_sweep.h"
#include "bench/policy_bench.h"
#include "bench/sweep.h"

namespace reflect {
namespace {

bool writeText(const std::string& path, const std::string& text) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return false;
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  return std::fclose(f) == 0 && ok;
}

// Rough readers: what the prefilter pass cost beside the faces it filters (issue 24's target:
// at most 0.5x a capture of the same faces).
void printFilterCosts(const std::vector<SweepRow>& rows) {
  bool header = false;
  for (const SweepRow& r : rows) {
    if (r.filterMs <= 0.0) continue;
    if (!header) {
      std::printf(
          "\nfiltering: the prefilter pass, or the box chains lobe taps read (medians a frame; the "
          "capture without it is the same faces):\n"
          "setting | capture ms (faces) | filter ms | filter / capture\n");
      header = true;
    }
    const double faces = r.captureMs - r.filterMs;
    std::printf("%s | %.2f | %.2f | %.2fx\n", r.setting.name.c_str(), faces, r.filterMs,
                faces > 0.0 ? r.filterMs / faces : 0.0);
  }
}

// Probe-lit objects: what projecting their probes' irradiance cost beside the capture it reads
// (issue 35's target: at most 0.05x the capture's time).
void printIrradianceCosts(const std::vector<SweepRow>& rows) {
  bool header = false;
  for (const SweepRow& r : rows) {
    if (r.irradianceMs <= 0.0) continue;
    if (!header) {
      std::printf(
          "\nirradiance projection (medians a frame):\n"
          "setting | capture ms (all before the main pass, less the projection) | projection ms | "
          "projection / capture\n");
      header = true;
    }
    const double faces = r.captureMs - r.irradianceMs;
    std::printf("%s | %.3f | %.3f | %.3fx\n", r.setting.name.c_str(), faces, r.irradianceMs,
                faces > 0.0 ? r.irradianceMs / faces : 0.0);
  }
}

// Rough readers: each rough mirror's own reflector PSNR (issue 24's target: >= 35 dB at roughness
// 0.3 and above under the default).
void printRoughErrors(const std::vector<SweepRow>& rows) {
  bool header = false;
  for (const SweepRow& r : rows) {
    if (r.roughPsnrDb.empty()) continue;
    if (!header) {
      std::printf("\nrough mirrors, each its own reflector PSNR dB (pooled over the times):\n");
      header = true;
    }
    std::printf("%s |", r.setting.name.c_str());
    for (const auto& [label, psnr] : r.roughPsnrDb) std::printf(" %s: %.2f |", label.c_str(), psnr);
    std::printf("\n");
  }
}

}  // namespace

int benchFramesDefault(BenchMode mode) {
  switch (mode) {
    case BenchMode::PolicyComparison:
    case BenchMode::SinglePolicy:
      return PolicyBenchOptions{}.frames;
    case BenchMode::Growth:
      return GrowthOptions{}.frames;
    case BenchMode::Sweep:
      return SweepOptions{}.frames;
    case BenchMode::Budget:
    case BenchMode::Costs:
      return 30;
    case BenchMode::LodSweep:
      return LodSweepOptions{}.frames;
    case BenchMode::ViewLodSweep:
      return 1;
  }
  return 0;
}

int benchWarmupDefault(BenchMode mode) {
  switch (mode) {
    case BenchMode::PolicyComparison:
    case BenchMode::SinglePolicy:
      return PolicyBenchOptions{}.warmup;
    case BenchMode::Growth:
      return GrowthOptions{}.warmup;
    case BenchMode::Sweep:
    case BenchMode::ViewLodSweep:
      return 0;
    case BenchMode::Budget:
      return 5;
    case BenchMode::Costs:
      return 3;
    case BenchMode::LodSweep:
      return LodSweepOptions{}.warmup;
  }
  return 0;
}

std::string runLodSweepCommand(const BenchCommandOptions& o, const BenchDemoFactory& makeDemo) {
  LodSweepOptions sweep;
  if (!o.times.empty()) sweep.times = o.times;
  return runCaptureLodSweep(o, makeDemo, sweep);
}

std::string runViewLodSweepCommand(const BenchCommandOptions& o, const BenchDemoFactory& makeDemo) {
  LodSweepOptions sweep;
  if (!o.times.empty()) sweep.viewTimes = o.times;
  return runViewLodSweep(o, makeDemo, sweep);
}

std::string runSinglePolicy(const BenchCommandOptions& o, const BenchDemoFactory& makeDemo) {
  const int frames = o.frames.value_or(benchFramesDefault(BenchMode::SinglePolicy));
  const int warmup = o.warmup.value_or(benchWarmupDefault(BenchMode::SinglePolicy));
  auto demo = makeDemo({});
  if (!demo) return demo.error();
  auto r = benchFrames(*demo.value(), o.width, o.height, warmup, frames);
  if (!r) return r.error();
  const BenchResult& b = r.value();
  std::printf(
      "policy %s, %d frames at %dx%d, cube %d: %d draw calls and %zu triangles in the "
      "last frame\n",
      policyName(o.planner.policy), frames, o.width, o.height, o.cubeSize, b.drawCallsPerFrame,
      b.trianglesPerFrame);
  std::printf("frame ms   median %.3f  p10 %.3f  p90 %.3f\n", median(b.frameMs),
              percentile(b.frameMs, 0.1), percentile(b.frameMs, 0.9));
  std::printf("cpu ms     median %.3f  p10 %.3f  p90 %.3f\n", median(b.cpuMs),
              percentile(b.cpuMs, 0.1), percentile(b.cpuMs, 0.9));
  std::printf("capture ms median %.3f  p10 %.3f  p90 %.3f\n", median(b.captureMs),
              percentile(b.captureMs, 0.1), percentile(b.captureMs, 0.9));
  return {};
}

std::string runPolicyComparison(const BenchCommandOptions& o, const BenchDemoFactory& makeDemo) {
  auto settings = [&](UpdatePolicy policy, float lod, float viewLod = 0.0f) {
    PlannerSettings s = o.planner;
    s.policy = policy;
    s.captureLod = lod;
    s.viewLod = viewLod;
    return s;
  };
  const float lod = o.planner.captureLod > 0 ? o.planner.captureLod : 0.5f;
  const float viewLod = o.planner.viewLod > 0 ? o.planner.viewLod : 0.5f;
  char lodLabel[64], viewLodLabel[80];
  std::snprintf(lodLabel, sizeof lodLabel, "when-changed + LOD (%.2g tris/px)", lod);
  std::snprintf(viewLodLabel, sizeof viewLodLabel, "when-changed + LOD, view LOD (%.2g, %.2g)", lod,
                viewLod);
  char sliceLabel[64], everyLabel[64];
  std::snprintf(sliceLabel, sizeof sliceLabel, "time-sliced (%d faces/frame)",
                o.planner.facesPerFrame);
  std::snprintf(everyLabel, sizeof everyLabel, "every-n (N = %d)", o.planner.everyN);
  const std::vector<PolicyCase> animated = {
      {"every-frame (the course)", settings(UpdatePolicy::EveryFrame, 0), false},
      {"when-changed (default)", settings(UpdatePolicy::WhenChanged, 0), false},
      {lodLabel, settings(UpdatePolicy::WhenChanged, lod), false},
      {viewLodLabel, settings(UpdatePolicy::WhenChanged, lod, viewLod), false},
      {sliceLabel, settings(UpdatePolicy::TimeSliced, 0), false},
      {everyLabel, settings(UpdatePolicy::EveryNFrames, 0), false},
  };
  const DemoFactory factory = [&](bool asPhong) {
    DemoVariant variant;
    variant.reflectorAsPhong = asPhong;
    return makeDemo(variant);
  };
  PolicyBenchOptions options;
  options.width = o.width;
  options.height = o.height;
  options.warmup = o.warmup.value_or(benchWarmupDefault(BenchMode::PolicyComparison));
  options.frames = o.frames.value_or(benchFramesDefault(BenchMode::PolicyComparison));
  options.accuracyFrames = o.accuracyFrames;

  std::printf("scene: Ex12-2%s%s, %dx%d, cube %d, %d frames after %d warm-up, 60 Hz steps\n\n",
              o.assets.empty() ? "" : " with models from ", o.assets.c_str(), o.width, o.height,
              o.cubeSize, options.frames, options.warmup);
  auto results = benchPolicies(factory, animated, options);
  if (!results) return results.error();
  std::printf("animated (the figures orbit):\n%s\n", formatPolicyTable(results.value()).c_str());
  const PolicyResult& original = results.value()[0];
  for (size_t i = 1; i < results.value().size(); ++i) {
    const PolicyResult& r = results.value()[i];
    std::printf("%s: frame time %.2fx every-frame's, %.2fx fewer triangles per frame\n",
                r.label.c_str(), r.medianMs / original.medianMs,
                original.trianglesPerFrame / std::max(r.trianglesPerFrame, 1.0));
  }

  options.dtSeconds = 0.0;  // nothing moves
  const std::vector<PolicyCase> still = {
      {"static: when-changed", settings(UpdatePolicy::WhenChanged, 0), false},
      {"static: reflector as plain Phong", settings(UpdatePolicy::WhenChanged, 0), true},
      {"static: every-frame (the course)", settings(UpdatePolicy::EveryFrame, 0), false},
  };
  auto stillResults = benchPolicies(factory, still, options);
  if (!stillResults) return stillResults.error();
  std::printf("\nstatic (time stopped):\n%s\n", formatPolicyTable(stillResults.value()).c_str());
  std::printf("static when-changed: frame time %.3fx the plain-Phong scene's\n",
              stillResults.value()[0].medianMs / stillResults.value()[1].medianMs);
  return {};
}

namespace {

// Keeps the settings `only` names, in its order (all when it is empty). Returns "" or a message
// naming the first unknown name and the names there are.
std::string keepOnly(const std::vector<std::string>& only, std::vector<SweepSetting>& settings) {
  if (only.empty()) return {};
  std::vector<SweepSetting> chosen;
  for (const std::string& name : only) {
    auto it = std::find_if(settings.begin(), settings.end(),
                           [&](const SweepSetting& s) { return s.name == name; });
    if (it == settings.end()) {
      std::string names;
      for (const SweepSetting& s : settings) names += (names.empty() ? "" : ", ") + s.name;
      return "--only: no sweep setting is called " + name + " (there are " + names + ")";
    }
    chosen.push_back(*it);
  }
  settings = chosen;
  return {};
}

}  // namespace

std::string runSweepCommand(const BenchCommandOptions& o, const BenchDemoFactory& makeDemo) {
  SweepOptions options;
  options.frames = o.frames.value_or(benchFramesDefault(BenchMode::Sweep));
  if (o.sweepSize) {
    options.width = o.sweepSize->x;
    options.height = o.sweepSize->y;
  }
  if (o.lobeSamples) options.reference.lobeSamples = *o.lobeSamples;
  // Times given: they are reported; the tuning times (where the constants were chosen, on the
  // default scene) are not measured.
  if (!o.times.empty()) {
    options.heldOutTimes = o.times;
    options.tunedTimes.clear();
  }
  std::vector<SweepSetting> settings = sweepSettings();
  const std::string unknown = keepOnly(o.only, settings);
  if (!unknown.empty()) return unknown;
  const SweepDemoFactory factory = [&]() {
    DemoVariant variant;
    variant.defaultAccuracy = true;
    return makeDemo(variant);
  };
  auto rows = runSweep(factory, settings, options);
  if (!rows) return rows.error();
  const auto timesText = [](const std::vector<double>& times) {
    std::string text;
    char t[16];
    for (double x : times) {
      std::snprintf(t, sizeof t, "%s%g", text.empty() ? "" : ", ", x);
      text += t;
    }
    return text;
  };
  std::printf(
      "sweep: scene %s, %dx%d, every-frame capture, %d timed frames per setting, errors over "
      "the reflector against the Embree reference at the held-out times t = %s s (the lookup's "
      "constants were chosen at t = 0, 1, ..., 7 s on the default scene; measured here: %s)\n\n%s",
      o.scene.c_str(), options.width, options.height, options.frames,
      timesText(options.heldOutTimes).c_str(),
      options.tunedTimes.empty() ? "none" : timesText(options.tunedTimes).c_str(),
      sweepTable(rows.value()).c_str());
  printFilterCosts(rows.value());
  printIrradianceCosts(rows.value());
  printRoughErrors(rows.value());
  const SweepRow* original = nullptr;
  const SweepRow* byDefault = nullptr;
  const SweepRow* centre = nullptr;
  for (const auto& r : rows.value()) {
    if (r.setting.name == "original") original = &r;
    if (r.setting.name == "default") byDefault = &r;
    if (r.setting.name == "centre") centre = &r;
  }
  if (original && byDefault && centre) {
    std::printf(
        "\ndefault vs original: %+.2f dB reflector PSNR (worst time %.2f against %.2f dB), "
        "%.1f against %.1f pixels off by more than 32 levels a frame, at %.2fx the frame time "
        "and %.2fx the CPU time\n",
        byDefault->psnrDb - original->psnrDb, byDefault->worstPsnrDb, original->worstPsnrDb,
        byDefault->visiblePerFrame, original->visiblePerFrame,
        byDefault->medianMs / original->medianMs, byDefault->cpuMs / original->cpuMs);
    std::printf(
        "default mean angular error %.3f deg = %.2fx the plain lookup's (centre) %.3f deg\n",
        byDefault->meanAngularErrorDeg,
        byDefault->meanAngularErrorDeg / centre->meanAngularErrorDeg, centre->meanAngularErrorDeg);
  }
  if (!o.csv.empty() && !writeText(o.csv, sweepCsv(rows.value()))) return o.csv + ": cannot write";
  if (!o.svg.empty() && !writeText(o.svg, sweepSvg(rows.value()))) return o.svg + ": cannot write";
  if (!o.csv.empty()) std::printf("wrote %s\n", o.csv.c_str());
  if (!o.svg.empty()) std::printf("wrote %s\n", o.svg.c_str());
  return {};
}

std::string runGrowthCommand(const BenchCommandOptions& o, const std::string& modelDirectory) {
  GrowthOptions options;
  options.width = o.width;
  options.height = o.height;
  options.frames = o.frames.value_or(benchFramesDefault(BenchMode::Growth));
  options.warmup = o.warmup.value_or(benchWarmupDefault(BenchMode::Growth));
  auto tables = runGrowthBench(modelDirectory, options);
  if (!tables) return tables.error();
  std::printf("growth: policy when-changed, figures orbiting, %dx%d, cube %d\n%s", o.width,
              o.height, 256, tables.value().c_str());
  return {};
}

}  // namespace reflect
