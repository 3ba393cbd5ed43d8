// `reflect`: the native, headless entry point (EGL surfaceless). Same scene, same shaders as the
// page; writes PNGs and prints timings.
#include <cstdio>
#include <string>
#include <vector>

#include "app/demo.h"
#include "app/headless_frames.h"
#include "bench/accuracy.h"
#include "bench/growth_bench.h"
#include "bench/policy_bench.h"
#include "bench/sweep.h"
#include "core/image.h"
#include "platform/native/cli_options.h"
#include "platform/native/egl_context.h"
#include "platform/native/model_paths.h"
#include "reference/reference_renderer.h"

namespace {

using reflect::CliOptions;
using reflect::Demo;
using reflect::Result;

int fail(const std::string& message) {
  std::fprintf(stderr, "reflect: %s\n", message.c_str());
  return 1;
}

Result<std::unique_ptr<Demo>> makeDemo(const CliOptions& o, bool reflectorAsPhong) {
  Result<reflect::Scene> loaded = reflect::loadNamedScene(o.scene);
  if (!loaded) return Result<std::unique_ptr<Demo>>::failure(loaded.error());
  reflect::Scene scene = loaded.take();
  if (reflectorAsPhong) {
    for (reflect::SceneObject& object : scene.objects) object.material = reflect::Material::Phong;
  }
  auto demo = std::make_unique<Demo>(scene);
  if (o.cubeSizeSet) {
    const std::string notice = demo->setCubeFaceSize(o.cubeSize);
    if (!notice.empty()) std::fprintf(stderr, "reflect: %s\n", notice.c_str());
  }
  demo->setPlannerSettings(o.planner);
  std::string accuracyError = demo->setAccuracySettings(o.accuracy);
  if (!accuracyError.empty()) return Result<std::unique_ptr<Demo>>::failure(accuracyError);
  demo->camera().setAngles(o.yawDeg, o.pitchDeg);
  std::string error = reflect::loadSceneModels(*demo, o.assets);
  if (error.empty()) error = demo->initGraphics();
  if (!error.empty()) return Result<std::unique_ptr<Demo>>::failure(error);
  return Result<std::unique_ptr<Demo>>(std::move(demo));
}

int runRender(const CliOptions& o) {
  auto demo = makeDemo(o, false);
  if (!demo) return fail(demo.error());
  auto image = reflect::renderFrameAt(*demo.value(), o.time, o.width, o.height);
  if (!image) return fail(image.error());
  std::string error = reflect::writePng(image.value(), o.out);
  if (!error.empty()) return fail(error);
  std::printf("wrote %s (%dx%d, t=%.3f s)\n", o.out.c_str(), o.width, o.height, o.time);
  if (o.referenceOut.empty()) return 0;
  auto report = reflect::measureAccuracy(*demo.value(), o.time, o.width, o.height);
  if (!report) return fail(report.error());
  error = reflect::writePng(report.value().referenceImage, o.referenceOut);
  if (!error.empty()) return fail(error);
  std::printf(
      "wrote %s; reflector: PSNR %.2f dB, RMSE %.2f, p95 %d, max %d, mean angular error "
      "%.3f deg\n",
      o.referenceOut.c_str(), report.value().reflector.psnrDb, report.value().reflector.rmse,
      report.value().reflector.p95PixelError, report.value().reflector.maxPixelError,
      report.value().meanAngularErrorDeg);
  return 0;
}

// One policy: frames of the animated default scene, median and spread.
int runSingleBench(const CliOptions& o) {
  auto demo = makeDemo(o, false);
  if (!demo) return fail(demo.error());
  auto r = reflect::benchFrames(*demo.value(), o.width, o.height, o.warmup, o.frames);
  if (!r) return fail(r.error());
  const reflect::BenchResult& b = r.value();
  std::printf(
      "policy %s, %d frames at %dx%d, cube %d: %d draw calls and %zu triangles in the "
      "last frame\n",
      reflect::policyName(o.planner.policy), o.frames, o.width, o.height, o.cubeSize,
      b.drawCallsPerFrame, b.trianglesPerFrame);
  std::printf("frame ms   median %.3f  p10 %.3f  p90 %.3f\n", reflect::median(b.frameMs),
              reflect::percentile(b.frameMs, 0.1), reflect::percentile(b.frameMs, 0.9));
  std::printf("capture ms median %.3f  p10 %.3f  p90 %.3f\n", reflect::median(b.captureMs),
              reflect::percentile(b.captureMs, 0.1), reflect::percentile(b.captureMs, 0.9));
  return 0;
}

// Every policy on the animated scene, then the static scene against a plain-Phong reflector.
int runPolicyBench(const CliOptions& o) {
  using reflect::PolicyCase;
  using reflect::UpdatePolicy;
  auto settings = [&](UpdatePolicy policy, float lod, float viewLod = 0.0f) {
    reflect::PlannerSettings s = o.planner;
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
  const reflect::DemoFactory factory = [&](bool asPhong) { return makeDemo(o, asPhong); };
  reflect::PolicyBenchOptions options;
  options.width = o.width;
  options.height = o.height;
  options.warmup = o.warmup;
  options.frames = o.frames;
  options.accuracyFrames = o.accuracyFrames;

  std::printf("scene: Ex12-2%s%s, %dx%d, cube %d, %d frames after %d warm-up, 60 Hz steps\n\n",
              o.assets.empty() ? "" : " with models from ", o.assets.c_str(), o.width, o.height,
              o.cubeSize, o.frames, o.warmup);
  auto results = reflect::benchPolicies(factory, animated, options);
  if (!results) return fail(results.error());
  std::printf("animated (the figures orbit):\n%s\n",
              reflect::formatPolicyTable(results.value()).c_str());
  const reflect::PolicyResult& original = results.value()[0];
  for (size_t i = 1; i < results.value().size(); ++i) {
    const reflect::PolicyResult& r = results.value()[i];
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
  auto stillResults = reflect::benchPolicies(factory, still, options);
  if (!stillResults) return fail(stillResults.error());
  std::printf("\nstatic (time stopped):\n%s\n",
              reflect::formatPolicyTable(stillResults.value()).c_str());
  std::printf("static when-changed: frame time %.3fx the plain-Phong scene's\n",
              stillResults.value()[0].medianMs / stillResults.value()[1].medianMs);
  return 0;
}

// Every accuracy setting against the ray-traced reference: table, CSV, SVG.
int runSweepBench(const CliOptions& o) {
  reflect::SweepOptions options;
  options.frames = o.frames == 120 ? 30 : o.frames;  // 120 is the bench default; 30 is enough here
  CliOptions plain = o;
  plain.accuracy = {};
  const reflect::SweepDemoFactory factory = [&]() { return makeDemo(plain, false); };
  auto rows = reflect::runSweep(factory, reflect::sweepSettings(), options);
  if (!rows) return fail(rows.error());
  std::printf(
      "sweep: scene %s, %dx%d, every-frame capture, %d timed frames per setting, errors "
      "over the reflector at t = 0, 2, 4 s against the Embree reference\n\n%s",
      o.scene.c_str(), options.width, options.height, options.frames,
      reflect::sweepTable(rows.value()).c_str());
  const reflect::SweepRow* original = nullptr;
  const reflect::SweepRow* byDefault = nullptr;
  const reflect::SweepRow* centre = nullptr;
  for (const auto& r : rows.value()) {
    if (r.setting.name == "original") original = &r;
    if (r.setting.name == "default") byDefault = &r;
    if (r.setting.name == "centre") centre = &r;
  }
  if (original && byDefault && centre) {
    std::printf("\ndefault vs original: %+.2f dB reflector PSNR at %.2fx the frame time\n",
                byDefault->psnrDb - original->psnrDb, byDefault->medianMs / original->medianMs);
    std::printf(
        "distance-corrected (default) mean angular error %.3f deg = %.2fx the plain "
        "lookup's (centre) %.3f deg\n",
        byDefault->meanAngularErrorDeg,
        byDefault->meanAngularErrorDeg / centre->meanAngularErrorDeg, centre->meanAngularErrorDeg);
  }
  auto write = [](const std::string& path, const std::string& text) {
    if (path.empty()) return true;
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    return std::fclose(f) == 0 && ok;
  };
  if (!write(o.csv, reflect::sweepCsv(rows.value()))) return fail(o.csv + ": cannot write");
  if (!write(o.svg, reflect::sweepSvg(rows.value()))) return fail(o.svg + ": cannot write");
  if (!o.csv.empty()) std::printf("wrote %s\n", o.csv.c_str());
  if (!o.svg.empty()) std::printf("wrote %s\n", o.svg.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  auto parsed = reflect::parseCli(std::vector<std::string>(argv + 1, argv + argc));
  if (!parsed) return fail(parsed.error());
  const CliOptions& o = parsed.value();
  if (o.command == "help") {
    std::fputs(reflect::cliHelp(), stdout);
    return 0;
  }
  auto context = reflect::HeadlessGlContext::create();
  if (!context) return fail(context.error());
  if (o.command == "render") return runRender(o);
  std::printf("GL: %s\n", context.value()->description().c_str());
  if (o.sweep) return runSweepBench(o);
  if (o.growth) {
    reflect::GrowthOptions options;
    options.width = o.width;
    options.height = o.height;
    auto tables = reflect::runGrowthBench(reflect::builtInModelDirectory(), options);
    if (!tables) return fail(tables.error());
    std::printf("growth: policy when-changed, figures orbiting, %dx%d, cube %d\n%s", o.width,
                o.height, 256, tables.value().c_str());
    return 0;
  }
  return o.policySet ? runSingleBench(o) : runPolicyBench(o);
}
