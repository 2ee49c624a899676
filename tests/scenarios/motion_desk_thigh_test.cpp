// The desk (scenarios/humanoid_sit_desk.yaml): the step that puts the left thigh on the seat, both
// soles held, moves and certifies. Its motion needs the two changes it failed without: the thigh,
// pinned by the three joints below it, approaches the seat free and meets it tangentially (its
// pair with the chair at d >= 0 rather than the 5 mm margin: PostureRequest::approaching), and the
// hands, over the desk top before and under its edge after, go round the edge by the detour
// (7980 projections of its 12000; it failed with 2500, and with 10000 without the first change).
#include <gtest/gtest.h>

#include "planner/motion/step_motion.h"
#include "tests/support/planned_scenario.h"

namespace stanceplan {
namespace {

TEST(MotionDeskThigh, TheLeftThighOntoTheSeatMovesAndCertifies) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_sit_desk.yaml"));
  SearchResult result = test::plan_with_one_process(scenario);
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  const Scene& scene = scenario.scene;
  std::vector<PlanStep>& steps = result.plan.steps;
  size_t thigh = 0;
  for (size_t i = 1; i < steps.size() && thigh == 0; ++i)
    if (steps[i].action == "add" && steps[i].changed &&
        scene.surfaces.id(scene.system, steps[i].changed->s1) == "robot/l_thigh")
      thigh = i;
  ASSERT_GT(thigh, 0u);
  StepMotionPlanner planner(scene, scenario.solver, MotionOptions{});
  StepMotionResult moved = planner.plan(steps[thigh - 1], steps[thigh]);
  ASSERT_EQ(moved.motion.status, MotionStatus::Solved) << moved.motion.message;
  EXPECT_LE(moved.solves, 12000 + 300 + 600);  // the detour's budgets and the straight travel's
  ASSERT_FALSE(moved.motion.samples.empty());
  // The plan up to that step, with that motion only, certifies sample by sample.
  steps.resize(thigh + 1);
  for (PlanStep& s : steps) s.motion.reset();
  steps[thigh].motion = std::move(moved.motion);
  test::expect_certified(scenario, result, "desk_thigh_with_motion");
}

}  // namespace
}  // namespace stanceplan
