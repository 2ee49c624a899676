// The computed guide (planner/guide/): the goal configuration carried towards the goal contacts,
// the validity rule, the milestones' spacing and form, determinism, and each stage's failure.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "planner/guide/goal_posture.h"
#include "planner/guide/guide_planner.h"
#include "planner/guide/guide_validity.h"
#include "planner/io/scenario.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using ::testing::StartsWith;

Scenario guide_free(const std::string& name) {
  return load_scenario(test::source_path("scenarios/guide_free/" + name));
}

double yaw_of(const Eigen::VectorXd& q) {
  const Eigen::Quaterniond r(q[3], q[4], q[5], q[6]);
  const Eigen::Matrix3d R = r.normalized().matrix();
  return std::atan2(R(1, 0), R(0, 0));
}

// The walk with a turn ends with the soles around (1, 1) facing +y: the waist is carried there and
// turned by 90 degrees before the solver starts.
TEST(GuideGoalPosture, TheInitialConfigurationIsCarriedAndTurnedTowardsTheGoalContacts) {
  const Scenario s = guide_free("walk_turn.yaml");
  const Eigen::VectorXd q = carried_configuration(s);
  EXPECT_NEAR(q[0], 1.0, 0.02);
  EXPECT_NEAR(q[1], 1.0, 0.02);
  EXPECT_NEAR(q[2], 0.90, 0.02);  // the soles start 8.5 mm off the floor
  EXPECT_NEAR(yaw_of(q), M_PI / 2, 1e-3);
  // The joints are the initial ones.
  EXPECT_EQ(q.tail(q.size() - 7), s.initial_configuration.tail(q.size() - 7));
}

TEST(GuideValidityRule, StandingIsValidSinkingOrFlyingIsNot) {
  const Scenario s = guide_free("walk.yaml");
  GuideValidity validity(s, s.initial_configuration, s.initial_configuration, s.guide);
  Eigen::VectorXd q = s.initial_configuration;
  EXPECT_TRUE(validity.valid(q)) << validity.why_invalid(q);
  q[2] = 0.05;  // the waist 5 cm up: the trunk in the floor (the legs may touch it)
  EXPECT_FALSE(validity.valid(q));
  EXPECT_NE(validity.why_invalid(q).find("env/"), std::string::npos) << validity.why_invalid(q);
  q[2] = 2.5;  // flying: no sole within reach of the floor
  EXPECT_FALSE(validity.valid(q));
  EXPECT_EQ(validity.why_invalid(q),
            "robot: no contact-capable surface within 0.45 m of a support");
}

// With every robot surface offered every surface of the room (contact pairs [robot/*, env/*]),
// only the links of the task's contacts (soles, thighs, forearms) may pass through the room's
// links: standing over the chair's seat puts the shanks in it, which is not valid, and the computed
// guide walks around the chair, as it does with the desk's own contact pairs.
TEST(GuideValidityRule, OnlyTheTasksSupportingLinksMayPassThroughTheRoom) {
  Scenario s = guide_free("desk.yaml");
  s.guide.contact_pairs = {{"robot/*", "env/*"}};
  GuideValidity validity(s, s.initial_configuration, s.initial_configuration, s.guide);
  Eigen::VectorXd q = s.initial_configuration;
  EXPECT_TRUE(validity.valid(q)) << validity.why_invalid(q);
  q.head<2>() << 1.52, -0.1;  // standing over the seat (x 1.295 to 1.745 m, y within 0.225 m)
  EXPECT_FALSE(validity.valid(q));
  EXPECT_THAT(validity.why_invalid(q), ::testing::HasSubstr("- env/chair"));

  const ComputedGuide g = compute_guide(s, s.guide);
  ASSERT_EQ(g.status, GuideStatus::Computed) << g.message;
  for (const auto* list : {&g.path, &g.milestone_configurations})
    for (const Eigen::VectorXd& c : *list) {
      if (c[2] < 0.85) continue;  // seated or sitting down: the goal is over the seat
      const bool over_seat = c[0] > 1.295 && c[0] < 1.745 && std::abs(c[1]) < 0.225;
      EXPECT_FALSE(over_seat) << "standing waist over the chair's seat at "
                              << c.head<3>().transpose();
    }
}

// Milestones at most `spacing` apart (base travel, a turn counted 0.5 m per radian), the last at
// the goal posture; positions only (a robot's heading is not stated), nothing else.
TEST(GuidePlanner, MilestonesAreSpacedAlongThePathAndEndAtTheGoalPosture) {
  const Scenario s = guide_free("walk_turn.yaml");
  const ComputedGuide g = compute_guide(s, s.guide);
  ASSERT_EQ(g.status, GuideStatus::Computed) << g.message;
  ASSERT_GE(g.milestones.size(), 5u);
  Eigen::Vector3d previous = s.initial_configuration.head<3>();
  for (const GuideMilestone& m : g.milestones) {
    ASSERT_EQ(m.roots.size(), 1u);
    EXPECT_EQ(m.roots[0].entity, 0);
    EXPECT_FALSE(m.roots[0].rpy.has_value());  // a robot's heading follows its feet
    EXPECT_LE((m.roots[0].position - previous).norm(), s.guide.spacing + 1e-9);
    previous = m.roots[0].position;
  }
  EXPECT_LT((previous - g.q_goal.head<3>()).norm(), 1e-9);
  EXPECT_NEAR(yaw_of(g.q_goal), M_PI / 2, 0.05);  // the goal posture faces +y
  EXPECT_EQ(g.milestone_configurations.back(), g.q_goal);
}

TEST(GuidePlanner, TheSameSeedGivesTheSameGuide) {
  const Scenario s = guide_free("stairs.yaml");
  const ComputedGuide a = compute_guide(s, s.guide), b = compute_guide(s, s.guide);
  ASSERT_EQ(a.status, GuideStatus::Computed) << a.message;
  ASSERT_EQ(a.path.size(), b.path.size());
  for (size_t i = 0; i < a.path.size(); ++i) EXPECT_EQ(a.path[i], b.path[i]) << "waypoint " << i;
  ASSERT_EQ(a.milestone_configurations.size(), b.milestone_configurations.size());
  EXPECT_EQ(a.raw_waypoints, b.raw_waypoints);
  EXPECT_EQ(a.leg_checks, b.leg_checks);
}

// The path planner's budget is counted in validity checks, never timed (issue 17): a budget of
// exactly the checks the stairs' path took gives the same path; a few checks give none, with the
// message naming the budget, and the same count twice, whatever the machine's speed.
TEST(GuidePlanner, TheBudgetCountsValidityChecksNotTime) {
  const Scenario s = guide_free("stairs.yaml");
  const ComputedGuide found = compute_guide(s, s.guide);
  ASSERT_EQ(found.status, GuideStatus::Computed) << found.message;
  ASSERT_EQ(found.leg_checks.size(), 1u);
  EXPECT_GT(found.leg_checks[0], 10);
  EXPECT_LT(found.leg_checks[0], s.guide.max_checks / 10);  // the default keeps a wide margin

  GuideOptions exact = s.guide;
  exact.max_checks = int(found.leg_checks[0]);
  const ComputedGuide again = compute_guide(s, exact);
  ASSERT_EQ(again.status, GuideStatus::Computed) << again.message;
  EXPECT_EQ(again.leg_checks, found.leg_checks);
  EXPECT_EQ(again.path, found.path);

  GuideOptions few = s.guide;
  few.max_checks = 10;
  const ComputedGuide a = compute_guide(s, few), b = compute_guide(s, few);
  EXPECT_EQ(a.status, GuideStatus::NoPath);
  EXPECT_THAT(a.message, StartsWith("guide: path: no collision-free path from the initial to the "
                                    "goal configuration within 10 validity checks "
                                    "(search.guide_max_checks;"));
  ASSERT_EQ(a.leg_checks.size(), 1u);
  EXPECT_EQ(a.leg_checks[0], 10);  // not one past it, though the stairs' path takes one iteration
  EXPECT_EQ(a.leg_checks, b.leg_checks);
  EXPECT_EQ(a.message, b.message);
}

TEST(GuidePlanner, AGoalStanceWithoutPostureFailsAtTheGoalPostureStage) {
  const Scenario s = load_scenario(test::source_path("tests/data/guide/feet_apart.yaml"));
  const ComputedGuide g = compute_guide(s, s.guide);
  EXPECT_EQ(g.status, GuideStatus::NoGoalPosture);
  EXPECT_THAT(g.message, StartsWith("guide: goal posture: no posture for the goal stance of "));
}

TEST(GuidePlanner, AGoalBehindAWallFailsAtThePathStageWithinItsBudget) {
  const Scenario s = load_scenario(test::source_path("tests/data/guide/behind_wall.yaml"));
  GuideOptions options = s.guide;
  options.max_checks = 2000;
  const ComputedGuide g = compute_guide(s, options);
  EXPECT_EQ(g.status, GuideStatus::NoPath);
  EXPECT_THAT(g.message, StartsWith("guide: path: no collision-free path from the initial to the "
                                    "goal configuration within 2000 validity checks"));
  ASSERT_EQ(g.leg_checks.size(), 1u);
  EXPECT_EQ(g.leg_checks[0], 2000);
}

}  // namespace
}  // namespace stanceplan
