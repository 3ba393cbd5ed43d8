#include "bench/budget_bench.h"

#include <cstdio>

#include "app/headless_frames.h"
#include "gfx/offscreen_target.h"

namespace reflect {

Result<BudgetBenchResult> runBudgetBench(const BenchDemoFactory& makeDemo, double budgetMs,
                                         int width, int height, int warmup, int frames) {
  using Out = Result<BudgetBenchResult>;
  Result<OffscreenTarget> target = OffscreenTarget::create(width, height);
  if (!target) return Out::failure(target.error());
  std::vector<std::unique_ptr<Demo>> demos;
  BudgetBenchResult result;
  for (;;) {
    auto demo = makeDemo({});
    if (!demo) return Out::failure(demo.error());
    if (result.candidates.empty()) {
      result.candidates = budgetCandidates(demo.value()->accuracySettings());
    }
    const BudgetCandidate& c = result.candidates[demos.size()];
    const std::string error = demo.value()->setAccuracySettings(c.accuracy);
    if (!error.empty()) return Out::failure(c.name + ": " + error);
    demos.push_back(demo.take());
    if (demos.size() == result.candidates.size()) break;
  }
  std::vector<Demo*> timed;
  for (auto& d : demos) timed.push_back(d.get());
  const auto step = [](size_t) { return 1.0 / 60.0; };
  timeInBlocks(timed, target.value().framebuffer(), width, height, warmup, step);
  const std::vector<TimedFrames> timings =
      timeInBlocks(timed, target.value().framebuffer(), width, height, frames, step);
  std::vector<std::vector<double>> ms(demos.size());
  for (size_t i = 0; i < demos.size(); ++i) ms[i] = timings[i].ms;
  for (size_t i = 0; i < demos.size(); ++i) {
    BudgetCandidate& c = result.candidates[i];
    c.frameMs = median(ms[i]);
    std::string error = demos[i]->setShowError(true);
    if (!error.empty()) return Out::failure(c.name + ": " + error);
    const FrameStats& s = demos[i]->frame(0.0, target.value().framebuffer(), width, height, true);
    if (!s.errorView) return Out::failure(c.name + ": the error view did not run");
    c.psnrDb = s.errorPsnrDb;
    demos[i].reset();
  }
  result.pick = pickWithinBudget(result.candidates, budgetMs);
  return result;
}

std::string runBudgetCommand(const BenchCommandOptions& o, const BenchDemoFactory& makeDemo) {
  const int frames = o.frames.value_or(30);
  const int warmup = o.warmup.value_or(5);
  auto r = runBudgetBench(makeDemo, o.budgetMs, o.width, o.height, warmup, frames);
  if (!r) return r.error();
  std::printf(
      "auto: scene %s, %dx%d, each search timed over %d frames (60 Hz steps, after %d "
      "warm-up), its reflector PSNR against the exact mode at the last frame\n"
      "   %-24s %9s    %16s\n%s\nauto picks %s\n",
      o.scene.c_str(), o.width, o.height, frames, warmup, "search", "median", "PSNR",
      r.value().pick.table.c_str(), r.value().pick.reason.c_str());
  return {};
}

}  // namespace reflect
