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

// scenarios/untuned/desk.yaml states four waist positions, the last the seated waist, and no
// joints: the posture change is what it leaves out. It is completed with the computed guide's:
// before its last milestone, the approach's last (standing at the crouch's footholds, heading
// stated) and the crouch, one-limb-free and seated stages (whole postures, their contacts); the
// last keeps its position and gets the last stage's heading and joints; the three before stay.
TEST(GuidePartial, ACoarseGuideToAChairGetsThePostureChangeItLeavesOut) {
  Scenario s = load_scenario(test::source_path("scenarios/untuned/desk.yaml"));
  ASSERT_TRUE(s.has_guide);
  ASSERT_EQ(s.milestones.size(), 4u);
  EXPECT_TRUE(unstated_moving_roots(s).empty());
  EXPECT_TRUE(states_no_joints(s));
  const std::vector<Eigen::VectorXd> written = s.milestones;
  const std::vector<Eigen::VectorXd> written_masks = s.milestone_masks;
  const std::optional<ComputedGuide> g = complete_written_guide(s, s.guide);
  ASSERT_TRUE(g.has_value());
  ASSERT_EQ(g->status, GuideStatus::Computed) << g->message;
  EXPECT_TRUE(g->completed_posture_change);
  ASSERT_EQ(g->stages, 4);
  ASSERT_EQ(s.milestones.size(), 8u);  // 3 written, approach, crouch, one limb free, seated, last
  ASSERT_EQ(s.milestone_masks.size(), 8u);
  ASSERT_EQ(s.milestone_tolerances.size(), 8u);
  ASSERT_EQ(s.milestone_contact_pairs.size(), 8u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(s.milestones[i], written[i]) << "milestone " << i;
    EXPECT_EQ(s.milestone_masks[i], written_masks[i]) << "milestone " << i;
  }
  const int joints = 7, n = int(s.milestones[0].size());
  EXPECT_TRUE(s.milestone_masks[3].segment<7>(0).isOnes());  // the approach: position, heading
  EXPECT_FALSE(s.milestone_masks[3].tail(n - joints).any());
  EXPECT_EQ(s.milestone_contact_pairs[3].size(), 2u);  // the soles
  for (size_t i = 4; i < 8; ++i)
    EXPECT_TRUE(s.milestone_masks[i].isOnes()) << "milestone " << i;  // whole postures
  EXPECT_EQ(s.milestone_contact_pairs[4].size(), 2u);                 // the crouch: the soles
  EXPECT_EQ(s.milestone_contact_pairs[6].size(), 4u);                 // seated: soles and thighs
  EXPECT_EQ(s.milestones[7].head<3>(), written[3].head<3>());         // the seated waist as written
  EXPECT_EQ(s.milestones[7].tail(n - joints), g->milestone_configurations.back().tail(n - joints));
  EXPECT_FALSE(states_no_joints(s));
}

// A guide that states joints (the hand-guided desk), or whose goal is no posture change (the
// untuned stairs: no joints, but the goal keeps none of the initial contacts), stays as written.
TEST(GuidePartial, AGuideWithJointsOrWithoutPostureChangeStaysAsWritten) {
  Scenario desk = load_scenario(test::source_path("scenarios/humanoid_sit_desk.yaml"));
  EXPECT_FALSE(states_no_joints(desk));
  EXPECT_FALSE(complete_written_guide(desk, desk.guide).has_value());
  Scenario stairs = load_scenario(test::source_path("scenarios/untuned/stairs.yaml"));
  EXPECT_TRUE(states_no_joints(stairs));
  const std::vector<Eigen::VectorXd> written = stairs.milestones;
  EXPECT_FALSE(complete_written_guide(stairs, stairs.guide).has_value());
  EXPECT_EQ(stairs.milestones, written);
}

// A whole guide (every moving root stated) is not partial.
TEST(GuidePartial, AWholeGuideIsNotPartial) {
  const Scenario s = load_scenario(test::source_path("scenarios/two_humanoids_table.yaml"));
  EXPECT_TRUE(unstated_moving_roots(s).empty());
}

}  // namespace
}  // namespace stanceplan
