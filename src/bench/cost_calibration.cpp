#include "bench/cost_calibration.h"

#include <cmath>
#include <cstdio>

#include "app/headless_frames.h"
#include "bench/policy_bench.h"
#include "gfx/offscreen_target.h"

namespace reflect {
namespace {

struct Setting {
  const char* name;
  bool asPhong;
  Search search;
  bool animated;  // the scene's time advances (else the first frame's time, every frame)
};

// The planner's count of what each method would do in this frame (search: planned).
Result<MethodChoice> countsOf(const BenchDemoFactory& makeDemo, int width, int height) {
  auto demo = makeDemo({});
  if (!demo) return Result<MethodChoice>::failure(demo.error());
  AccuracySettings planned = demo.value()->accuracySettings();
  planned.search = Search::Planned;
  const std::string error = demo.value()->setAccuracySettings(planned);
  if (!error.empty()) return Result<MethodChoice>::failure(error);
  Result<OffscreenTarget> target = OffscreenTarget::create(width, height);
  if (!target) return Result<MethodChoice>::failure(target.error());
  // Two frames, so the second counts the faces that moving objects redraw.
  for (int i = 0; i < 2; ++i) {
    demo.value()->frame(1.0 / 60.0, target.value().framebuffer(), width, height, true);
  }
  const std::vector<MethodChoice>& choices = demo.value()->methodChoices();
  if (choices.empty()) return Result<MethodChoice>::failure("the planner weighed no reflector");
  MethodChoice total = choices[0];
  for (size_t i = 1; i < choices.size(); ++i) {
    total.trace.pixels += choices[i].trace.pixels;
    total.capture.faces += choices[i].capture.faces;
    total.capture.triangles += choices[i].capture.triangles;
    total.capture.texels += choices[i].capture.texels;
    total.capture.pixels += choices[i].capture.pixels;
  }
  return total;
}

}  // namespace

std::string runCostCalibration(const BenchCommandOptions& o, const BenchDemoFactory& makeDemo) {
  const int width = o.sweepSize ? o.sweepSize->x : 512;
  const int height = o.sweepSize ? o.sweepSize->y : 512;
  const int frames = o.frames.value_or(30);
  const int warmup = o.warmup.value_or(3);
  Result<MethodChoice> counts = countsOf(makeDemo, width, height);
  if (!counts) return counts.error();
  const MethodChoice& c = counts.value();

  const Setting settings[] = {{"phong (no reflection)", true, Search::Plain, true},
                              {"traced (exact)", false, Search::Exact, true},
                              {"captured + searched", false, Search::Hierarchical, true},
                              {"searched alone (still)", false, Search::Hierarchical, false}};
  constexpr size_t kSettings = sizeof settings / sizeof settings[0];
  std::vector<std::unique_ptr<Demo>> demos;
  for (const Setting& s : settings) {
    DemoVariant variant;
    variant.reflectorAsPhong = s.asPhong;
    auto demo = makeDemo(variant);
    if (!demo) return demo.error();
    AccuracySettings accuracy = demo.value()->accuracySettings();
    accuracy.search = s.search;
    const std::string error = demo.value()->setAccuracySettings(accuracy);
    if (!error.empty()) return std::string(s.name) + ": " + error;
    demos.push_back(demo.take());
  }
  Result<OffscreenTarget> target = OffscreenTarget::create(width, height);
  if (!target) return target.error();
  std::vector<Demo*> timed;
  for (auto& d : demos) timed.push_back(d.get());
  bool first = true;  // the still setting holds its first frame's time
  const auto step = [&](size_t i) {
    const double dt = settings[i].animated || first ? 1.0 / 60.0 : 0.0;
    if (i == kSettings - 1) first = false;
    return dt;
  };
  timeInBlocks(timed, target.value().framebuffer(), width, height, warmup, step);
  const std::vector<TimedFrames> timings =
      timeInBlocks(timed, target.value().framebuffer(), width, height, frames, step);
  std::vector<std::vector<double>> ms(kSettings);
  for (size_t i = 0; i < kSettings; ++i) ms[i] = timings[i].ms;
  double m[kSettings];
  for (size_t i = 0; i < kSettings; ++i) m[i] = median(ms[i]);

  std::printf(
      "cost calibration: scene %s%s%s, %dx%d, %d frames a setting after %d warm-up, "
      "interleaved\n",
      o.scene.c_str(), o.assets.empty() ? "" : ", models from ", o.assets.c_str(), width, height,
      frames, warmup);
  std::printf(
      "  planner's counts: %.0f mirror pixels, %.0f scene triangles (%.2f levels), "
      "a frame captured as it moves: %.2f faces, %.0f triangles, %.0f texels\n",
      c.trace.pixels, c.trace.triangles, std::log2(std::max(c.trace.triangles, 1.0)),
      c.capture.faces, c.capture.triangles, c.capture.texels);
  for (size_t i = 0; i < kSettings; ++i) {
    std::printf("  %-26s median %8.2f ms\n", settings[i].name, m[i]);
  }
  const double pixels = std::max(c.trace.pixels, 1.0);
  const double trace = (m[1] - m[0]) / pixels;
  const double search = (m[3] - m[0]) / pixels;
  const double capture = m[2] - m[3];
  std::printf("  trace:   %.3g ms a mirror pixel (traced - phong), %.3g ms a pixel per level\n",
              trace, trace / std::max(std::log2(std::max(c.trace.triangles, 2.0)), 1.0));
  std::printf("  search:  %.3g ms a mirror pixel (searched alone - phong)\n", search);
  std::printf(
      "  capture: %.3g ms a frame as the scene moves (captured - searched alone): "
      "%.3g ms a face, or %.3g ms a triangle, or %.3g ms a texel, if it were all one\n",
      capture, capture / std::max(c.capture.faces, 1e-9),
      capture / std::max(c.capture.triangles, 1.0), capture / std::max(c.capture.texels, 1.0));
  return {};
}

}  // namespace reflect
