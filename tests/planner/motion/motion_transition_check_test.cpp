// The motion planner as the search's transition check (motion_transition_check.h): the walk planned
// with it comes with the motion of every step, the same motion add_motion computes afterwards,
// and certifies sample by sample.
#include <gtest/gtest.h>

#include "planner/motion/motion_transition_check.h"
#include "planner/motion/plan_motion.h"
#include "planner/search/stance_search.h"
#include "tests/support/paths.h"
#include "tests/support/planned_scenario.h"
#include "tests/support/planned_with_motion.h"

namespace stanceplan {
namespace {

TEST(MotionTransitionCheck, TheWalkPlannedWithItCarriesEveryStepsMotionAndCertifies) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  auto [result, checks] = test::plan_with_motion(scenario);
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  EXPECT_EQ(result.transitions_dropped, 0);
  ASSERT_EQ(checks.size(), result.plan.steps.size() - 1);
  EXPECT_EQ(result.transitions_checked, int(checks.size()));
  for (const StepMotionResult& r : checks) {
    EXPECT_EQ(r.motion.status, MotionStatus::Solved) << r.motion.message;
    EXPECT_TRUE(r.motion.samples.empty());  // moved into the plan
    EXPECT_GT(r.solves, 0);
  }
  // The same motion as computing it after the search.
  Plan after = result.plan;
  ASSERT_TRUE(add_motion(scenario.scene, scenario.solver, MotionOptions{}, after).solved());
  for (size_t i = 1; i < after.steps.size(); ++i) {
    ASSERT_TRUE(result.plan.steps[i].motion.has_value()) << "step " << i;
    const auto& during = result.plan.steps[i].motion->samples;
    const auto& later = after.steps[i].motion->samples;
    ASSERT_EQ(during.size(), later.size()) << "step " << i;
    for (size_t k = 0; k < during.size(); ++k)
      EXPECT_LE((during[k].q - later[k].q).norm(), 1e-9) << "step " << i << " sample " << k;
  }
  test::expect_certified(scenario, result, "walk_checked_motion");
}

}  // namespace
}  // namespace stanceplan
