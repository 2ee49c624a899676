// The hand-over of a carried object (planner/guide/hand_over.h): found where no carrier reaches
// both ends, solved with both carriers grasping, and the guide's path passes through it.
#include <gtest/gtest.h>

#include "planner/guide/guide_planner.h"
#include "planner/guide/hand_over.h"
#include "planner/io/scenario.h"
#include "planner/model/kinematics.h"
#include "planner/solver/posture_solver.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

Scenario guide_free(const std::string& name) {
  return load_scenario(test::source_path("scenarios/guide_free/" + name));
}

// Platform A is out of arm 2's reach, platform B out of arm 1's: arm 1 hands the cylinder to arm 2,
// each with its two pads on two opposed facets, at a posture the solver balanced.
TEST(GuideHandOver, TheCylinderPassesFromTheArmThatReachesAToTheOneThatReachesB) {
  const Scenario s = guide_free("dual_arm.yaml");
  const ComputedGuide g = compute_guide(s, s.guide);
  ASSERT_EQ(g.status, GuideStatus::Computed) << g.message;
  std::string note;
  const std::optional<HandOver> h = find_hand_over(s, g.q_goal, s.guide, &note);
  ASSERT_TRUE(h.has_value()) << note;
  const System& system = s.scene.system;
  EXPECT_EQ(system.entity(h->from).name, "arm1");
  EXPECT_EQ(system.entity(h->to).name, "arm2");
  ASSERT_EQ(h->grasps.size(), 4u);
  const std::vector<ModelData> data = system_kinematics(system, h->q);
  int on_arm1 = 0, on_arm2 = 0;
  for (const StanceContact& c : h->grasps) {
    EXPECT_EQ(c.contact.s2.entity, h->object);
    on_arm1 += c.contact.s1.entity == h->from;
    on_arm2 += c.contact.s1.entity == h->to;
    // E8-E9: every pad lies on its facet's plane, facing it.
    const Surface& pad = s.scene.surfaces.get(c.contact.s1);
    const Surface& facet = s.scene.surfaces.get(c.contact.s2);
    const Eigen::Isometry3d T_WP =
        data[size_t(c.contact.s1.entity)].T_WL[size_t(pad.link)] * pad.T_LS;
    const Eigen::Isometry3d T_WF =
        data[size_t(c.contact.s2.entity)].T_WL[size_t(facet.link)] * facet.T_LS;
    EXPECT_NEAR((T_WF.inverse() * T_WP.translation()).z(), 0.0, 1e-4);
    EXPECT_NEAR(T_WP.linear().col(2).dot(T_WF.linear().col(2)), -1.0, 1e-4);
  }
  EXPECT_EQ(on_arm1, 2);
  EXPECT_EQ(on_arm2, 2);
  // The hand-over posture is a solution of its stance: solved again from itself, it stays solved.
  const PostureSolver solver(s.scene, s.solver);
  EXPECT_EQ(solver.solve(s.loaded_request(h->grasps, h->q)).status, PostureStatus::Solved);
  // The guide passes through it: a milestone at the hand-over's cylinder position, between both
  // platforms, stating the position only (the task does not turn the cylinder).
  ASSERT_GT(g.hand_over_milestone, 0);
  ASSERT_LT(g.hand_over_milestone, int(g.milestones.size()));
  const GuideMilestone& m = g.milestones[size_t(g.hand_over_milestone - 1)];
  ASSERT_EQ(m.roots.size(), 1u);
  const int at = system.offset(h->object) + Entity::kBasePosition;
  EXPECT_LT((m.roots[0].position - h->q.segment<3>(at)).norm(), 1e-9);
  EXPECT_FALSE(m.roots[0].rpy.has_value());
  EXPECT_GT(m.roots[0].position.x(), -0.4);
  EXPECT_LT(m.roots[0].position.x(), 0.4);
}

// The cylinder moved 2 cm towards arm 2: platform A is then within arm 2's stretched chain (the
// reach bound, necessary, not sufficient), yet none of arm 2's grasps holds the cylinder there, so
// the hand-over is still found. Before the grasps were tried at both ends, the guide carried the
// cylinder straight over, offering every contact, and the search from this start found no plan in
// 3798 solver calls (57 now).
TEST(GuideHandOver, ACarrierWithinTheReachBoundThatCannotGraspTheObjectDoesNotCarryItAlone) {
  Scenario s = guide_free("dual_arm.yaml");
  const System& system = s.scene.system;
  int cylinder = -1;
  for (int e = 0; e < system.num_entities(); ++e)
    if (system.entity(e).name == "cyl") cylinder = e;
  ASSERT_GE(cylinder, 0);
  s.initial_configuration[system.offset(cylinder) + Entity::kBasePosition] += 0.02;
  const ComputedGuide g = compute_guide(s, s.guide);
  ASSERT_EQ(g.status, GuideStatus::Computed) << g.message;
  std::string note;
  const std::optional<HandOver> h = find_hand_over(s, g.q_goal, s.guide, &note);
  ASSERT_TRUE(h.has_value()) << note;
  EXPECT_EQ(system.entity(h->from).name, "arm1");
  EXPECT_EQ(system.entity(h->to).name, "arm2");
  EXPECT_GT(g.hand_over_milestone, 0);
}

// One hand reaches the pen where it starts and where it ends: nothing to hand over.
TEST(GuideHandOver, AnObjectOneCarrierReachesAtBothEndsIsNotHandedOver) {
  const Scenario s = guide_free("pen.yaml");
  const ComputedGuide g = compute_guide(s, s.guide);
  ASSERT_EQ(g.status, GuideStatus::Computed) << g.message;
  EXPECT_EQ(g.hand_over_milestone, 0);
  EXPECT_EQ(g.hand_over_note, "");
}

}  // namespace
}  // namespace stanceplan
