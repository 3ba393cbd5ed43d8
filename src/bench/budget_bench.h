// `reflect bench --budget MS`: what "auto" does in the page, natively. Each search (plain, linear,
// hierarchical with 1 and 2 layers, exact) is timed on the scene, interleaved frame by frame, and
// its reflector error measured against the exact mode with the error view; then the rule of
// core/budget_pick.h picks. Prints the table and the pick.
#pragma once

#include <string>

#include "bench/bench_commands.h"
#include "core/budget_pick.h"
#include "core/result.h"

namespace reflect {

struct BudgetBenchResult {
  std::vector<BudgetCandidate> candidates;
  BudgetPick pick;
};

// `frames` timed frames after `warmup` (60 Hz steps from t = 0), then the error at the last one.
Result<BudgetBenchResult> runBudgetBench(const BenchDemoFactory& makeDemo, double budgetMs,
                                         int width, int height, int warmup, int frames);

std::string runBudgetCommand(const BenchCommandOptions& options, const BenchDemoFactory& makeDemo);

}  // namespace reflect
