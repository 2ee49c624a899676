// The desk (scenarios/humanoid_sit_desk.yaml) planned as `plan --motion` plans it: the search
// checks the motion of each transition of the plan it finds (lazy validation, stance_search.h) and
// drops the ones without; the plan it returns moves at every step and certifies sample by sample.
// Which transitions get dropped depends on the plan first found (with lazy expansion by default:
// one, measured; before it, the right sole set back on the floor under a leg whose thigh was on
// the seat, with no detour within 12000 projections): every dropped one is a check that failed.
// The plan also holds the two changes the motion needed to lay a thigh on the seat: the thigh,
// pinned by the three joints below it, approaches the seat free and meets it tangentially
// (PostureRequest::approaching), and the hands go round the desk's edge by the detour.
#include <gtest/gtest.h>

#include "tests/support/planned_scenario.h"
#include "tests/support/planned_with_motion.h"

namespace stanceplan {
namespace {

TEST(MotionDesk, ThePlanFoundWithItsMotionCheckedMovesAtEveryStepAndCertifies) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_sit_desk.yaml"));
  const auto [result, checks] = test::plan_with_motion(scenario);
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  int dropped = 0;
  for (const StepMotionResult& r : checks) dropped += r.motion.status != MotionStatus::Solved;
  EXPECT_EQ(dropped, result.transitions_dropped);
  for (size_t i = 1; i < result.plan.steps.size(); ++i) {
    ASSERT_TRUE(result.plan.steps[i].motion.has_value()) << "step " << i;
    EXPECT_EQ(result.plan.steps[i].motion->status, MotionStatus::Solved) << "step " << i;
  }
  const Scene& scene = scenario.scene;
  bool thigh = false;
  for (const PlanStep& step : result.plan.steps)
    thigh = thigh || (step.action == "add" && step.changed &&
                      scene.surfaces.id(scene.system, step.changed->s1) == "robot/l_thigh");
  EXPECT_TRUE(thigh) << "the plan lays the left thigh on the seat";
  test::expect_certified(scenario, result, "desk_with_motion");
}

}  // namespace
}  // namespace stanceplan
