// The computed guide's phases (planner/guide/contact_phases.h, approach.h, partial_guide.h): the
// goal's steadying contacts come last by the goal posture's own forces, a robot that changes its
// posture walks to its goal footholds first, and a partial guide is completed with the computed
// path's poses of the roots it leaves out.
#include <gtest/gtest.h>

#include <numeric>

#include "planner/guide/approach.h"
#include "planner/guide/contact_phases.h"
#include "planner/guide/goal_posture.h"
#include "planner/guide/guide_planner.h"
#include "planner/guide/partial_guide.h"
#include "planner/io/scenario.h"
#include "planner/model/kinematics.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

Scenario guide_free(const std::string& name) {
  return load_scenario(test::source_path("scenarios/guide_free/" + name));
}

int goal_index(const Scenario& s, const std::string& s1) {
  for (size_t c = 0; c < s.goal_stance.size(); ++c)
    if (s.scene.surfaces.id(s.scene.system, s.goal_stance[c].contact.s1) == s1) return int(c);
  return -1;
}

// Seated at the desk the thighs carry most of the weight, the forearms little: the forearms are
// offered last, the thighs (and the feet, which the initial stance has) are not.
TEST(GuideContactPhases, TheDesksForearmsSteadyAndComeLastTheThighsCarry) {
  const Scenario s = guide_free("desk.yaml");
  const PostureResult goal = solve_goal_posture(s);
  ASSERT_EQ(goal.status, PostureStatus::Solved) << goal.message;
  const ContactPhases phases = order_goal_contacts(s, goal);
  ASSERT_EQ(phases.shares.size(), s.goal_stance.size());
  EXPECT_NEAR(std::accumulate(phases.shares.begin(), phases.shares.end(), 0.0), 1.0, 1e-9);
  const int thigh = goal_index(s, "robot/l_thigh"), forearm = goal_index(s, "robot/l_forearm");
  ASSERT_GE(thigh, 0);
  ASSERT_GE(forearm, 0);
  EXPECT_LT(phases.shares[size_t(forearm)],
            ContactPhases::kSteadyingShare * phases.shares[size_t(thigh)]);
  const std::vector<std::pair<std::string, std::string>> last = {
      {"robot/l_forearm", "env/desk_top"}, {"robot/r_forearm", "env/desk_top"}};
  EXPECT_EQ(phases.last, last);
}

// A walk's new contacts are its feet, each carrying about half: none comes last.
TEST(GuideContactPhases, AWalksFeetAllCarry) {
  const Scenario s = guide_free("side_step.yaml");
  const PostureResult goal = solve_goal_posture(s);
  ASSERT_EQ(goal.status, PostureStatus::Solved) << goal.message;
  EXPECT_TRUE(order_goal_contacts(s, goal).last.empty());
}

// The desk's robot sits down (joints change by far more than kPostureChange): it first stands on
// the goal posture's footholds in its initial posture, the soles where the goal has them.
TEST(GuideApproach, TheDeskIsApproachedStandingOnTheGoalFootholds) {
  const Scenario s = guide_free("desk.yaml");
  const PostureResult goal = solve_goal_posture(s);
  ASSERT_EQ(goal.status, PostureStatus::Solved) << goal.message;
  const std::optional<Approach> a = approach_configuration(s, goal.q);
  ASSERT_TRUE(a.has_value());
  const int n = int(s.initial_configuration.size());
  EXPECT_EQ(a->q.tail(n - 7), s.initial_configuration.tail(n - 7));  // standing joints
  // Floor to floor (the initial soles are 8.5 mm above it, the goal's on it).
  EXPECT_NEAR(a->q[2], s.initial_configuration[2], 0.01);
  const auto at_goal = system_kinematics(s.scene.system, goal.q);
  const auto at_approach = system_kinematics(s.scene.system, a->q);
  Eigen::Vector3d mean_goal = Eigen::Vector3d::Zero(), mean_approach = Eigen::Vector3d::Zero();
  for (const char* sole : {"robot/l_sole", "robot/r_sole"}) {
    const SurfaceRef ref = *s.scene.surfaces.find(s.scene.system, sole);
    const Surface& surface = s.scene.surfaces.get(ref);
    mean_goal += (at_goal[0].T_WL[size_t(surface.link)] * surface.T_LS).translation() / 2;
    mean_approach += (at_approach[0].T_WL[size_t(surface.link)] * surface.T_LS).translation() / 2;
  }
  EXPECT_LT((mean_goal - mean_approach).norm(), 1e-6);
  const std::vector<std::pair<std::string, std::string>> kept = {{"robot/l_sole", "env/floor"},
                                                                 {"robot/r_sole", "env/floor"}};
  EXPECT_EQ(a->kept, kept);
}

TEST(GuideApproach, AWalkNeedsNone) {
  const Scenario s = guide_free("walk.yaml");
  const PostureResult goal = solve_goal_posture(s);
  ASSERT_EQ(goal.status, PostureStatus::Solved) << goal.message;
  EXPECT_FALSE(approach_configuration(s, goal.q).has_value());
}

// The desk's computed guide: the approach's milestones offer the soles only and keep the standing
// height; the goal milestone states the seated joints.
TEST(GuideApproach, TheDesksGuideWalksOnItsSolesThenSitsDown) {
  const Scenario s = guide_free("desk.yaml");
  const ComputedGuide g = compute_guide(s, s.guide);
  ASSERT_EQ(g.status, GuideStatus::Computed) << g.message;
  ASSERT_GT(g.approach_milestones, 0);
  ASSERT_GT(int(g.milestones.size()), g.approach_milestones);
  for (int k = 0; k < g.approach_milestones; ++k) {
    EXPECT_EQ(g.milestones[size_t(k)].contacts.size(), 2u) << "milestone " << k;
    EXPECT_NEAR(g.milestones[size_t(k)].roots[0].position.z(), s.initial_configuration[2], 0.05)
        << "milestone " << k;
  }
  EXPECT_TRUE(g.milestones.back().contacts.empty());
  ASSERT_TRUE(g.milestones.back().roots[0].joints.has_value());
  EXPECT_EQ(*g.milestones.back().roots[0].joints, g.q_goal.tail(g.q_goal.size() - 7));
}

// scenarios/guide_free/table_partial.yaml states the table's milestones only: both robots must move
// (their goal soles are placed ahead), so they are completed; the table's stated entries stay.
TEST(GuidePartial, ARootNoMilestoneStatesIsCompletedAlongThePath) {
  Scenario s = load_scenario(test::source_path("scenarios/guide_free/table_partial.yaml"));
  ASSERT_TRUE(s.has_guide);
  const int r1 = s.scene.system.find_entity("r1"), r2 = s.scene.system.find_entity("r2"),
            table = s.scene.system.find_entity("table");
  EXPECT_EQ(unstated_moving_roots(s), (std::vector<int>{r1, r2}));
  const std::vector<Eigen::VectorXd> written = s.milestones;
  const ComputedGuide g = compute_guide(s, s.guide);
  ASSERT_EQ(g.status, GuideStatus::Computed) << g.message;
  complete_milestones(s, g, {r1, r2});
  EXPECT_TRUE(unstated_moving_roots(s).empty());
  const int o1 = s.scene.system.offset(r1), ot = s.scene.system.offset(table);
  double x = s.initial_configuration[o1];
  for (size_t i = 0; i < s.milestones.size(); ++i) {
    EXPECT_EQ(s.milestones[i].segment<7>(ot), written[i].segment<7>(ot)) << "milestone " << i;
    EXPECT_TRUE(s.milestone_masks[i].segment<3>(o1).isOnes()) << "milestone " << i;
    EXPECT_GT(s.milestones[i][o1], x) << "r1 walks forward, milestone " << i;
    x = s.milestones[i][o1];
  }
  EXPECT_NEAR(x, g.q_goal[o1], 1e-9);  // the last milestone at the goal posture
}

// A whole guide (every moving root stated) is not partial.
TEST(GuidePartial, AWholeGuideIsNotPartial) {
  const Scenario s = load_scenario(test::source_path("scenarios/two_humanoids_table.yaml"));
  EXPECT_TRUE(unstated_moving_roots(s).empty());
}

}  // namespace
}  // namespace stanceplan
