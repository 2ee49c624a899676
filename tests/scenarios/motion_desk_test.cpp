// The desk (scenarios/humanoid_sit_desk.yaml) planned as `plan --motion` plans it: the search
// checks the motion of each transition of the plan it finds (lazy validation, stance_search.h) and
// drops the ones without. The plan first found sets the right foot back on the floor from a leg
// stretched under the desk, the right thigh already on the seat: pinned at the thigh, the foot
// cannot reach its placement without going through the floor (no detour within 12000 projections).
// That transition is dropped and the plan found next moves at every step and certifies sample by
// sample. It also holds the two changes the motion needed to lay the left thigh on the seat: the
// thigh, pinned by the three joints below it, approaches the seat free and meets it tangentially
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
  EXPECT_GE(result.transitions_dropped, 1);  // the foot under the stretched leg
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
