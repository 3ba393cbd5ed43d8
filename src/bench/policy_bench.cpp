#include "bench/policy_bench.h"

#include <algorithm>
#include <cstdio>

#include "app/headless_frames.h"
#include "gfx/offscreen_target.h"

namespace reflect {
namespace {

struct Samples {
  std::vector<double> frameMs, captureMs;
  double faces = 0, captureDraws = 0, captureTriangles = 0, triangles = 0;
};

Result<std::vector<std::unique_ptr<Demo>>> makeAll(const DemoFactory& makeDemo,
                                                   const std::vector<PolicyCase>& cases) {
  std::vector<std::unique_ptr<Demo>> demos;
  for (const PolicyCase& c : cases) {
    auto demo = makeDemo(c.reflectorAsPhong);
    if (!demo) return Result<std::vector<std::unique_ptr<Demo>>>::failure(demo.error());
    demo.value()->setPlannerSettings(c.settings);
    demos.push_back(demo.take());
  }
  return demos;
}

}  // namespace

Result<std::vector<PolicyResult>> benchPolicies(const DemoFactory& makeDemo,
                                                const std::vector<PolicyCase>& cases,
                                                const PolicyBenchOptions& o) {
  using Out = Result<std::vector<PolicyResult>>;
  Result<OffscreenTarget> target = OffscreenTarget::create(o.width, o.height);
  if (!target) return Out::failure(target.error());
  const GLuint fb = target.value().framebuffer();

  // Timing: every case's demo advances together, one frame each in turn.
  auto demos = makeAll(makeDemo, cases);
  if (!demos) return Out::failure(demos.error());
  std::vector<Samples> samples(cases.size());
  for (int frame = 0; frame < o.warmup + o.frames; ++frame) {
    for (size_t c = 0; c < cases.size(); ++c) {
      const FrameStats& s =
          demos.value()[c]->frame(frame == 0 ? 0.0 : o.dtSeconds, fb, o.width, o.height, true);
      if (frame < o.warmup) continue;
      Samples& out = samples[c];
      out.frameMs.push_back(s.frameMs);
      out.captureMs.push_back(s.captureMs);
      out.faces += s.facesCaptured;
      out.captureDraws += s.captureDrawCalls;
      out.captureTriangles += static_cast<double>(s.captureTriangles);
      out.triangles += static_cast<double>(s.triangles());
    }
  }
  demos.value().clear();

  std::vector<PolicyResult> results;
  for (size_t c = 0; c < cases.size(); ++c) {
    const Samples& s = samples[c];
    const double n = static_cast<double>(o.frames);
    PolicyResult r;
    r.label = cases[c].label;
    r.medianMs = median(s.frameMs);
    r.p10Ms = percentile(s.frameMs, 0.1);
    r.p90Ms = percentile(s.frameMs, 0.9);
    r.captureMedianMs = median(s.captureMs);
    r.facesPerFrame = s.faces / n;
    r.captureDrawsPerFrame = s.captureDraws / n;
    r.captureTrianglesPerFrame = s.captureTriangles / n;
    r.trianglesPerFrame = s.triangles / n;
    r.maxStalenessFrames = cases[c].settings.maxStalenessFrames();
    results.push_back(r);
  }

  // Accuracy: each case against the course's every-frame scheme, frame by frame.
  PolicyCase referenceCase{"every-frame", {}, false};
  referenceCase.settings.policy = UpdatePolicy::EveryFrame;
  for (size_t c = 0; c < cases.size(); ++c) {
    if (cases[c].reflectorAsPhong) {
      results[c].maxDifference = -1;  // a different picture by design: no accuracy to compare
      continue;
    }
    auto pair = makeAll(makeDemo, {referenceCase, cases[c]});
    if (!pair) return Out::failure(pair.error());
    for (int frame = 0; frame < o.accuracyFrames; ++frame) {
      RgbaImage images[2];
      for (int k = 0; k < 2; ++k) {
        pair.value()[static_cast<size_t>(k)]->frame(frame == 0 ? 0.0 : o.dtSeconds, fb, o.width,
                                                    o.height, false);
        images[k] = target.value().readPixels();
      }
      auto d = compareImages(images[0], images[1], 0);
      if (!d) return Out::failure(d.error());
      results[c].maxDifference = std::max(results[c].maxDifference, d.value().maxChannel);
      results[c].differingPixels = std::max(results[c].differingPixels, d.value().fractionOver);
    }
  }
  return results;
}

std::string formatPolicyTable(const std::vector<PolicyResult>& results) {
  std::string out =
      "| policy | frame ms median (p10-p90) | capture ms | faces/frame | capture draws/frame | "
      "capture tris/frame | all tris/frame | max staleness (frames) | max diff vs every-frame "
      "(levels; worst-frame pixels) |\n|---|---|---|---|---|---|---|---|---|\n";
  char line[512];
  for (const PolicyResult& r : results) {
    char accuracy[64] = "n/a";
    if (r.maxDifference >= 0) {
      std::snprintf(accuracy, sizeof accuracy, "%d; %.3f%%", r.maxDifference,
                    100.0 * r.differingPixels);
    }
    std::snprintf(line, sizeof line,
                  "| %s | %.2f (%.2f-%.2f) | %.2f | %.2f | %.1f | %.0f | %.0f | %d | %s |\n",
                  r.label.c_str(), r.medianMs, r.p10Ms, r.p90Ms, r.captureMedianMs, r.facesPerFrame,
                  r.captureDrawsPerFrame, r.captureTrianglesPerFrame, r.trianglesPerFrame,
                  r.maxStalenessFrames, accuracy);
    out += line;
  }
  return out;
}

}  // namespace reflect
