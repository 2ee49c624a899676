// The stall rule of a solve (planner/solver/stall_monitor.h), with the parameters measured on the
// untuned scenarios (after 40, window 30, factor 1.1, near feasibility 0.01): a violation that
// stays flat is stopped at the first iteration the rule allows, one that keeps falling is never
// stopped, nor is one already near feasibility, nor any with the default (off) rule.
#include "planner/solver/stall_monitor.h"

#include <gtest/gtest.h>

#include <cmath>

namespace stanceplan {
namespace {

StallRule measured_rule() {
  StallRule rule;
  rule.after = 40;
  rule.window = 30;
  rule.factor = 1.1;
  rule.near_feasible = 0.01;
  return rule;
}

int first_stop(StallMonitor& monitor, double (*violation)(int)) {
  for (int k = 0; k < 100; ++k)
    if (monitor.stalled(k, violation(k))) return k;
  return -1;
}

TEST(StallMonitor, AFlatViolationStopsAtTheFirstIterationAllowed) {
  StallMonitor monitor(measured_rule(), 100);
  EXPECT_EQ(first_stop(monitor, [](int) { return 0.315; }), 40);
  EXPECT_EQ(monitor.reason(),
            "constraint violation 0.315 at iteration 40, best 0.315 over the last 30 iterations, "
            "not 1.1x below 0.315 (best up to iteration 10)");
}

TEST(StallMonitor, AViolationHalvedEveryThirtyIterationsIsNeverStopped) {
  StallMonitor monitor(measured_rule(), 100);
  EXPECT_EQ(first_stop(monitor, [](int k) { return 0.5 * std::pow(0.5, k / 30.0); }), -1);
}

TEST(StallMonitor, AFallSlowerThanTenPercentPerWindowIsStopped) {
  StallMonitor monitor(measured_rule(), 100);
  // 7 % less every 30 iterations.
  EXPECT_EQ(first_stop(monitor, [](int k) { return 0.5 * std::pow(0.93, k / 30.0); }), 40);
}

TEST(StallMonitor, NearFeasibilityAndTheDefaultRuleNeverStop) {
  StallMonitor converging(measured_rule(), 100);
  EXPECT_EQ(first_stop(converging, [](int) { return 9e-3; }), -1);
  StallMonitor by_default(StallRule{}, 100);
  EXPECT_EQ(first_stop(by_default, [](int) { return 0.315; }), -1);
}

TEST(StallMonitor, ADropInsideTheWindowKeepsTheSolveGoing) {
  StallMonitor monitor(measured_rule(), 100);
  // 0.3 flat, one iterate at 0.2 at iteration 40: the window keeps it in view up to iteration 69;
  // at 70 it is the best before the window and nothing since has improved on it.
  EXPECT_EQ(first_stop(monitor, [](int k) { return k == 40 ? 0.2 : 0.3; }), 70);
}

// The progress budget (StallRule::budget; 30 / 20 / 10 as the search uses it): a flat violation
// stops once its 30 iterations are spent; every new decade buys 20 more from where it was reached;
// a violation near feasibility is never stopped.
StallRule budget_rule() {
  StallRule rule;
  rule.budget = 30;
  rule.extension = 20;
  rule.progress_factor = 10.0;
  return rule;
}

TEST(ProgressBudget, AFlatViolationStopsWhenItsBudgetIsSpent) {
  StallMonitor monitor(budget_rule(), 100);
  EXPECT_EQ(first_stop(monitor, [](int) { return 0.315; }), 31);
  EXPECT_EQ(monitor.reason(),
            "no progress within its iteration budget: constraint violation 0.315 at iteration 31, "
            "not 10x below 0.315 since iteration 0");
}

TEST(ProgressBudget, EachNewDecadeBuysMoreIterations) {
  StallMonitor monitor(budget_rule(), 100);
  // 0.9 up to iteration 24, then 0.05 (a decade below 0.9) from 25 on: 25 + 20 = 45 allowed.
  EXPECT_EQ(first_stop(monitor, [](int k) { return k < 25 ? 0.9 : 0.05; }), 46);
  // A fall of a decade every 15 iterations, down to feasibility: never stopped.
  StallMonitor falling(budget_rule(), 100);
  EXPECT_EQ(first_stop(falling, [](int k) { return std::pow(10.0, -k / 15.0); }), -1);
}

TEST(ProgressBudget, ASolveNearFeasibilityIsNeverStopped) {
  StallMonitor monitor(budget_rule(), 100);
  EXPECT_EQ(first_stop(monitor, [](int) { return 9e-3; }), -1);
  // Off by default: no budget.
  StallMonitor by_default(StallRule{}, 100);
  EXPECT_EQ(first_stop(by_default, [](int) { return 0.9; }), -1);
}

}  // namespace
}  // namespace stanceplan
