#pragma once
// For the tests of whole scenarios (tests/scenarios/, label slow): the motion between the steps of
// a scenario's plan (planner/motion/), computed as `plan --motion` does, every step's motion found,
// and the plan with its motion certified through its file, sample by sample.
#include <gtest/gtest.h>

#include <string>

#include "planner/motion/plan_motion.h"
#include "tests/support/planned_scenario.h"

namespace stanceplan::test {

inline void expect_motion_certified(const Scenario& scenario, SearchResult result,
                                    const std::string& name) {
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  const PlanMotionSummary summary =
      add_motion(scenario.scene, scenario.solver, MotionOptions{}, result.plan);
  for (size_t i = 0; i < summary.steps.size(); ++i)
    EXPECT_EQ(summary.steps[i].motion.status, MotionStatus::Solved)
        << name << ": no motion into step " << i + 1 << ": " << summary.steps[i].motion.message;
  for (size_t i = 1; i < result.plan.steps.size(); ++i)
    ASSERT_TRUE(result.plan.steps[i].motion.has_value()) << "step " << i;
  expect_certified(scenario, result, name + "_with_motion");
}

}  // namespace stanceplan::test
