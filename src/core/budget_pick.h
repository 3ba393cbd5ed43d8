// The frame-budget pick ("auto" accuracy): given each candidate setting's measured frame time and
// its error against the exact mode on the current scene, the most accurate one that fits the
// budget. The rule alone lives here (no GL, unit-tested); the caller does the timing and the
// error measurement (the page on the user's machine, `reflect bench --budget` natively).
#pragma once

#include <string>
#include <vector>

#include "core/accuracy_settings.h"

namespace reflect {

struct BudgetCandidate {
  std::string name;  // e.g. "hierarchical, layers 2"
  AccuracySettings accuracy;
  double frameMs = 0.0;  // measured on this machine
  double psnrDb = 0.0;   // reflector PSNR against the exact mode (kPsnrCapDb when identical)
};

struct BudgetPick {
  int index = -1;      // into the candidates; -1 when there were none
  bool fits = false;   // within the budget (else: nothing fits, and this is the fastest)
  std::string reason;  // "hierarchical, layers 2: 14.1 ms of a 16.7 ms budget, 36.2 dB"
  std::string table;   // one line per candidate, the pick marked
};

// The settings "auto" times: `base` (the user's other accuracy settings) with each search: plain,
// linear, hierarchical with 1 and 2 layers, exact.
std::vector<BudgetCandidate> budgetCandidates(const AccuracySettings& base);
// "plain", "hierarchical, layers 2", "exact".
std::string candidateName(const AccuracySettings& accuracy);

// The highest PSNR among the candidates whose frame time is within `budgetMs` (ties: the faster);
// when none is, the fastest. A candidate with a frame time that is not a finite positive number
// is never picked while another is.
BudgetPick pickWithinBudget(const std::vector<BudgetCandidate>& candidates, double budgetMs);

}  // namespace reflect
