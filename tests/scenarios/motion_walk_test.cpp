// The walk (scenarios/humanoid_walk.yaml) with its motion (planner/motion/): every step's motion
// is found and the plan, read back from its file (format @2), certifies sample by sample.
#include <gtest/gtest.h>

#include "planner/motion/plan_motion.h"
#include "tests/support/planned_scenario.h"

namespace stanceplan {
namespace {

TEST(MotionWalk, EveryStepMovesAndCertifiesSampleBySample) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  SearchResult result = test::plan_with_one_process(scenario);
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  const PlanMotionSummary summary =
      add_motion(scenario.scene, scenario.solver, MotionOptions{}, result.plan);
  EXPECT_TRUE(summary.solved()) << summary.first_failure;
  size_t samples = 0;
  for (size_t i = 1; i < result.plan.steps.size(); ++i) {
    ASSERT_TRUE(result.plan.steps[i].motion.has_value());
    samples += result.plan.steps[i].motion->samples.size();
  }
  EXPECT_GE(samples, result.plan.steps.size());  // feet lift 3 cm and travel: many samples a step
  test::expect_certified(scenario, result, "walk_with_motion");
}

}  // namespace
}  // namespace stanceplan
