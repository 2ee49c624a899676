// The hand with round fingertips (assets/robots/hand/hand_round.urdf) turns the ball with point
// contacts (scenarios/hand_ball_rotate_point.yaml): the plan is found within the scenario's node
// budget and certified through its file, every contact is a point contact, three fingertips or
// more hold the ball at every step, and the ball ends upside down.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/planned_scenario.h"

namespace stanceplan {
namespace {

TEST(HandBallRotatePoint, PlanCertifiedWithPointFingertips) {
  const Scenario scenario =
      load_scenario(test::source_path("scenarios/hand_ball_rotate_point.yaml"));
  const SearchResult result = test::plan_with_one_process(scenario);
  test::expect_certified(scenario, result, "hand_ball_rotate_point");
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  const auto& steps = result.plan.steps;
  std::printf("[ figures  ] %zu steps, %d solver calls, %d nodes expanded\n", steps.size(),
              result.solver_calls, result.nodes_expanded);
  ASSERT_GE(steps.size(), 9u);  // every fingertip moved at least once
  for (const PlanStep& step : steps) {
    int loaded = 0;
    for (const PlanContact& c : step.contacts) {
      loaded += c.loaded;
      EXPECT_TRUE(scenario.scene.surfaces.get(c.contact.s1).is_point());
    }
    EXPECT_GE(loaded, 3) << "step " << &step - steps.data();
  }
  for (const Contact& c : steps.back().stance.contacts())
    EXPECT_EQ(scenario.scene.surfaces.get(c.s2).name[0], 'n');  // northern faces
  const int ball = scenario.scene.system.find_entity("ball");
  const Eigen::Vector4d q =
      steps.back().q.segment<4>(scenario.scene.system.offset(ball) + Entity::kBaseQuaternion);
  EXPECT_LT(2.0 * std::acos(std::min(1.0, std::abs(q[1]) / q.norm())), 0.5) << q.transpose();
}

}  // namespace
}  // namespace stanceplan
