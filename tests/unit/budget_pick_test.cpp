// core/budget_pick.h: the frame-budget pick, fed tables of measured times and errors.
#include <gtest/gtest.h>

#include "core/budget_pick.h"
#include "core/error_metrics.h"

namespace reflect {
namespace {

std::vector<BudgetCandidate> table() {
  std::vector<BudgetCandidate> c = budgetCandidates(AccuracySettings{});
  // plain, linear, hierarchical 1, hierarchical 2, exact
  const double ms[] = {9.0, 12.0, 14.1, 15.0, 80.0};
  const double db[] = {27.0, 33.0, 35.0, 36.2, kPsnrCapDb};
  for (size_t i = 0; i < c.size(); ++i) {
    c[i].frameMs = ms[i];
    c[i].psnrDb = db[i];
  }
  return c;
}

TEST(BudgetPick, CandidatesCoverEverySearch) {
  const auto c = budgetCandidates(AccuracySettings{});
  ASSERT_EQ(c.size(), 5u);
  EXPECT_EQ(c[0].name, "plain");
  EXPECT_EQ(c[3].name, "hierarchical, layers 2");
  EXPECT_EQ(c[4].accuracy.search, Search::Exact);
}

TEST(BudgetPick, TheMostAccurateThatFits) {
  const auto c = table();
  for (double budget : {5.0, 9.0, 10.0, 13.0, 14.5, 16.7, 33.3, 100.0}) {
    const BudgetPick pick = pickWithinBudget(c, budget);
    ASSERT_GE(pick.index, 0);
    const BudgetCandidate& p = c[static_cast<size_t>(pick.index)];
    if (pick.fits) {
      EXPECT_LE(p.frameMs, budget);
      for (const BudgetCandidate& other : c) {
        if (other.frameMs <= budget) {
          EXPECT_GE(p.psnrDb, other.psnrDb);
        }
      }
    } else {
      for (const BudgetCandidate& other : c) EXPECT_GT(other.frameMs, budget);
    }
  }
  EXPECT_EQ(c[static_cast<size_t>(pickWithinBudget(c, 16.7).index)].name, "hierarchical, layers 2");
  EXPECT_EQ(pickWithinBudget(c, 16.7).reason,
            "hierarchical, layers 2: 15.0 ms of a 16.7 ms budget, 36.2 dB");
  EXPECT_EQ(c[static_cast<size_t>(pickWithinBudget(c, 100).index)].name, "exact");
  EXPECT_EQ(c[static_cast<size_t>(pickWithinBudget(c, 10).index)].name, "plain");
}

TEST(BudgetPick, NothingFitsGivesTheFastest) {
  const BudgetPick pick = pickWithinBudget(table(), 5.0);
  EXPECT_FALSE(pick.fits);
  EXPECT_EQ(pick.index, 0);
  EXPECT_NE(pick.reason.find("nothing fits"), std::string::npos);
}

TEST(BudgetPick, UnmeasuredIsNeverPicked) {
  auto c = table();
  c[4].frameMs = 0.0;  // exact not timed
  c[3].frameMs = std::nan("");
  const BudgetPick pick = pickWithinBudget(c, 1000.0);
  EXPECT_EQ(pick.index, 2);
  EXPECT_NE(pick.table.find("->"), std::string::npos);
}

TEST(BudgetPick, TiesGoToTheFaster) {
  auto c = table();
  c[2].psnrDb = c[3].psnrDb;
  EXPECT_EQ(pickWithinBudget(c, 20.0).index, 2);
}

}  // namespace
}  // namespace reflect
