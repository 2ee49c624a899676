// The posture change in stages (planner/guide/posture_stages.h): the desk's robot crouches on its
// feet, lands one thigh with the other leg's foot free, sits, then lays its forearms on the desk,
// each stage a solved posture placed where the seated one has its contacts.
#include <gtest/gtest.h>

#include <cmath>

#include "planner/guide/contact_phases.h"
#include "planner/guide/goal_posture.h"
#include "planner/guide/guide_milestones.h"
#include "planner/guide/guide_planner.h"
#include "planner/guide/posture_stages.h"
#include "planner/io/scenario.h"
#include "planner/solver/posture_solver.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

Scenario guide_free(const std::string& name) {
  return load_scenario(test::source_path("scenarios/guide_free/" + name));
}

std::vector<PostureStage> stages_of(const Scenario& s, int* solves) {
  const PostureResult goal = solve_goal_posture(s);
  EXPECT_EQ(goal.status, PostureStatus::Solved) << goal.message;
  return posture_stages(s, goal.q, order_goal_contacts(s, goal), solves);
}

const StanceContact& goal_contact(const Scenario& s, const std::string& s1) {
  for (const StanceContact& c : s.goal_stance)
    if (s.scene.surfaces.id(s.scene.system, c.contact.s1) == s1) return c;
  throw std::runtime_error("no goal contact of " + s1);
}

TEST(GuidePostureStages, TheDeskCrouchesLandsAThighSitsThenReaches) {
  const Scenario s = guide_free("desk.yaml");
  int solves = 0;
  const std::vector<PostureStage> stages = stages_of(s, &solves);
  ASSERT_EQ(stages.size(), 4u);
  EXPECT_EQ(solves, 4);
  EXPECT_EQ(stages[0].name, "crouch");
  EXPECT_EQ(stages[1].name, "one limb free");
  EXPECT_EQ(stages[2].name, "seated");
  EXPECT_EQ(stages[3].name, "goal");
  // The crouch stands on the soles only and offers only them; the robot's base sinks from the
  // standing height towards the seat, and stays above the seated one.
  const std::vector<std::pair<std::string, std::string>> soles = {{"robot/l_sole", "env/floor"},
                                                                  {"robot/r_sole", "env/floor"}};
  EXPECT_EQ(stages[0].offered, soles);
  EXPECT_LT(stages[0].q[2], s.initial_configuration[2] - 0.1);
  EXPECT_GT(stages[0].q[2], stages[2].q[2] + 0.05);
  EXPECT_EQ(stages[2].offered.size(), 4u);  // soles and thighs
  EXPECT_TRUE(stages[3].offered.empty());   // every pair
  // The goal adds the forearms where the seated posture has its soles and thighs.
  for (const char* s1 : {"robot/l_sole", "robot/r_sole", "robot/l_thigh", "robot/r_thigh"}) {
    const Contact& c = goal_contact(s, s1).contact;
    const Placement a = measure_placement(s.scene, c, stages[2].q);
    const Placement b = measure_placement(s.scene, c, stages[3].q);
    EXPECT_NEAR(a.x, b.x, 1e-4) << s1;
    EXPECT_NEAR(a.y, b.y, 1e-4) << s1;
  }
}

// A walk keeps its feet and adds no contact that carries weight otherwise: no stages.
TEST(GuidePostureStages, AWalkHasNone) {
  const Scenario s = guide_free("walk.yaml");
  int solves = 0;
  EXPECT_TRUE(stages_of(s, &solves).empty());
  EXPECT_EQ(solves, 0);
}

// The desk's guide walks to the crouch's footholds on its soles, then follows the stages, each
// milestone stating its joints.
TEST(GuidePostureStages, TheDesksGuideEndsWithTheStages) {
  const Scenario s = guide_free("desk.yaml");
  const ComputedGuide g = compute_guide(s, s.guide);
  ASSERT_EQ(g.status, GuideStatus::Computed) << g.message;
  ASSERT_EQ(g.stages, 4);
  ASSERT_EQ(int(g.milestones.size()), g.approach_milestones + g.stages);
  for (size_t k = size_t(g.approach_milestones); k < g.milestones.size(); ++k)
    EXPECT_TRUE(g.milestones[k].roots[0].joints.has_value()) << "milestone " << k;
  // Each stage states its whole posture, its heading too (the seated robot faces the desk), and
  // so does the approach's last milestone, where the robot stands to sit down: a node
  // turned from them does not reach them. The walk before states positions only.
  const System& system = s.scene.system;
  const int w = system.offset(g.milestones[0].roots[0].entity) + Entity::kBaseQuaternion;
  for (int k = g.approach_milestones - 1; k < int(g.milestones.size()); ++k) {
    const GuideMilestone::Root& root = g.milestones[size_t(k)].roots[0];
    ASSERT_TRUE(root.rpy.has_value()) << "milestone " << k;
    const Eigen::Vector3d rpy = base_rpy(g.milestone_configurations[size_t(k)].segment<4>(w));
    EXPECT_LT((*root.rpy - rpy).norm(), 1e-9) << "milestone " << k;
  }
  EXPECT_LT(std::abs((*g.milestones.back().roots[0].rpy)[2]), 0.05);  // seated facing the desk (+x)
  for (int k = 0; k + 1 < g.approach_milestones; ++k)
    EXPECT_FALSE(g.milestones[size_t(k)].roots[0].rpy.has_value()) << "milestone " << k;
}

}  // namespace
}  // namespace stanceplan
