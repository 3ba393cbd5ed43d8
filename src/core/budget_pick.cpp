#include "core/budget_pick.h"

#include <cmath>
#include <cstdio>

#include "core/error_metrics.h"

namespace reflect {
namespace {

std::string formatMs(double ms) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", ms);
  return text;
}

std::string formatDb(double db) {
  if (db >= kPsnrCapDb) return "exact (inf dB)";
  char text[32];
  std::snprintf(text, sizeof text, "%.1f dB", db);
  return text;
}

bool measured(const BudgetCandidate& c) {
  return std::isfinite(c.frameMs) && c.frameMs > 0.0;
}

}  // namespace

std::string candidateName(const AccuracySettings& a) {
  std::string name = searchName(a.search);
  if (a.search == Search::Hierarchical) name += ", layers " + std::to_string(a.layers);
  return name;
}

std::vector<BudgetCandidate> budgetCandidates(const AccuracySettings& base) {
  std::vector<BudgetCandidate> list;
  const auto add = [&](Search search, int layers) {
    AccuracySettings a = base;
    a.search = search;
    a.layers = layers;
    list.push_back({candidateName(a), a, 0.0, 0.0});
  };
  add(Search::Plain, base.layers);
  add(Search::Linear, base.layers);
  add(Search::Hierarchical, 1);
  add(Search::Hierarchical, 2);
  add(Search::Exact, base.layers);
  return list;
}

BudgetPick pickWithinBudget(const std::vector<BudgetCandidate>& candidates, double budgetMs) {
  BudgetPick pick;
  int best = -1, fastest = -1;
  for (size_t i = 0; i < candidates.size(); ++i) {
    const BudgetCandidate& c = candidates[i];
    if (!measured(c)) continue;
    const int index = static_cast<int>(i);
    if (fastest < 0 || c.frameMs < candidates[static_cast<size_t>(fastest)].frameMs) {
      fastest = index;
    }
    if (!(c.frameMs <= budgetMs)) continue;
    if (best < 0) {
      best = index;
      continue;
    }
    const BudgetCandidate& b = candidates[static_cast<size_t>(best)];
    if (c.psnrDb > b.psnrDb || (c.psnrDb == b.psnrDb && c.frameMs < b.frameMs)) best = index;
  }
  pick.fits = best >= 0;
  pick.index = best >= 0 ? best : fastest;
  if (pick.index < 0 && !candidates.empty()) pick.index = 0;  // nothing measured: the first
  const std::string budget = formatMs(budgetMs) + " ms budget";
  if (pick.index >= 0) {
    const BudgetCandidate& c = candidates[static_cast<size_t>(pick.index)];
    pick.reason =
        c.name + ": " + formatMs(c.frameMs) + " ms of a " + budget + ", " + formatDb(c.psnrDb);
    if (!pick.fits) pick.reason = "nothing fits; the fastest, " + pick.reason;
  }
  for (size_t i = 0; i < candidates.size(); ++i) {
    const BudgetCandidate& c = candidates[i];
    char line[160];
    std::snprintf(line, sizeof line, "%s %-24s %9s ms %16s%s\n",
                  static_cast<int>(i) == pick.index ? "->" : "  ", c.name.c_str(),
                  measured(c) ? formatMs(c.frameMs).c_str() : "-", formatDb(c.psnrDb).c_str(),
                  measured(c) && c.frameMs <= budgetMs ? "" : "  (over budget)");
    pick.table += line;
  }
  return pick;
}

}  // namespace reflect
