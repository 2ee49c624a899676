// Untuned scenarios (scenarios/untuned/README.md): search at its defaults, contact pairs by whole
// families, base-position guides. Counts, never wall time: solver calls are deterministic with one
// solver process, so these bound them (the targets of bench/untuned_bench: at most 2 calls per
// step) and check the plans certify.
#include <gtest/gtest.h>

#include "planner/search/stance_search.h"
#include "tests/support/paths.h"
#include "tests/support/planned_scenario.h"

namespace stanceplan {
namespace {

SearchResult plan_untuned(const Scenario& scenario) {
  SearchOptions options = scenario.search;
  options.threads = 1;
  return StanceSearch(scenario, options).run();
}

// The walk with a turn: repeated hopeless candidates (knees on the floor from the same standing
// posture) are deferred (failure_memo.h): 2 calls per step, the target.
TEST(Untuned, TheWalkWithATurnPlansWithTwoSolverCallsPerStep) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/untuned/walk_turn.yaml"));
  const SearchResult result = plan_untuned(scenario);
  test::expect_certified(scenario, result, "untuned_walk_turn");
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  EXPECT_LE(result.solver_calls, 2 * static_cast<int>(result.plan.steps.size()));
}

// The dual-arm hand-over with pads on any facet: a side of the standing cylinder is never offered
// on a platform or the floor (candidates.h, rigid bodies); 558 calls were measured with that rule
// alone (1000 before), for 19 steps.
TEST(Untuned, TheDualArmHandOverPlansWithoutImpossibleCylinderContacts) {
  const Scenario scenario =
      load_scenario(test::source_path("scenarios/untuned/dual_arm_handover.yaml"));
  const SearchResult result = plan_untuned(scenario);
  test::expect_certified(scenario, result, "untuned_dual_arm_handover");
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  EXPECT_LE(result.solver_calls, 558);
}

}  // namespace
}  // namespace stanceplan
