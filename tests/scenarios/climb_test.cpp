// The paper's fifth scenario (docs/METHOD.md section 5.5): scenarios/humanoid_climb_on_robot.yaml,
// planned within its own budget and certified. A humanoid crosses the gap between two platforms
// by stepping on the hands (palms up, raised over the head) of a second humanoid standing on the
// floor in the gap.
//
// Why the palms are held overhead with the wrists bent back (the supporter's limits: shoulder_p
// 110 N m, elbow_p 70, wrist_p 35, wrist_y 30, wrist_r 25; the climber weighs 572 N): a palm more
// than 110 / 572 = 0.19 m in front of the shoulder axis (any palm held up in front of the body)
// exceeds shoulder_p's limit. With the arm vertical the load is nearly over the shoulder and elbow
// axes, wrist_y and wrist_r are vertical (no gravity torque), and wrist_p (horizontal, across the
// hand) carries the lever from the wrist axis to the centre of pressure: the palm spans 0.03-0.13 m
// from the wrist axis, so the whole climber on one palm needs its centre of pressure within
// 35 / 572 = 0.061 m of the wrist. The plan has wrist_p at that limit whenever one palm carries the
// climber alone.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "planner/search/stance_search.h"
#include "tests/support/paths.h"
#include "tests/support/planned_scenario.h"
#include "tests/support/scenario_motion.h"

namespace stanceplan {
namespace {

const std::string kLeftPalm = "supporter/l_palm-climber/l_sole";
const std::string kRightPalm = "supporter/r_palm-climber/r_sole";

// Vertical force the step's contacts whose s1 or s2 is on `entity` exert on it (N, +z up).
double vertical_support(const PlanStep& step, int entity) {
  double f_z = 0.0;
  for (const VertexForce& f : step.forces) {
    const Contact& c = step.contacts[f.contact].contact;
    // force_W acts on s1; s2 receives the opposite (Newton's third law).
    if (c.s1.entity == entity) f_z += f.force_W.z();
    if (c.s2.entity == entity) f_z -= f.force_W.z();
  }
  return f_z;
}

// Made at some step and broken at a later one.
struct MadeAndBroken {
  bool made = false, broken = false;
  void see(bool in_stance) {
    if (in_stance) made = true;
    if (!in_stance && made) broken = true;
  }
};

TEST(ClimbOnRobotPlan, PlansCertifiesAndTheClimberCrossesOnTheSupportersHands) {
  const Scenario scenario =
      load_scenario(test::source_path("scenarios/humanoid_climb_on_robot.yaml"));
  const SearchResult result = StanceSearch(scenario, scenario.search).run();
  test::expect_certified(scenario, result, "humanoid_climb_on_robot");
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;

  const System& system = scenario.scene.system;
  const int climber = system.find_entity("climber");
  const int supporter = system.find_entity("supporter");
  const int env = system.find_entity("env");
  const double g = 9.81;
  const double m_climber = system.entity(climber).model->total_mass;
  const double m_supporter = system.entity(supporter).model->total_mass;
  const auto& steps = result.plan.steps;
  MadeAndBroken left, right;
  int alone_on_a_palm = 0;
  for (size_t i = 0; i < steps.size(); ++i) {
    const auto ids = test::stance_ids(scenario, steps[i].stance);
    // The supporter's feet never move, the climber never touches the floor, and the climber's
    // soles touch the supporter only through its palms.
    EXPECT_EQ(ids.count("supporter/l_sole-env/floor"), 1u) << "step " << i;
    EXPECT_EQ(ids.count("supporter/r_sole-env/floor"), 1u) << "step " << i;
    EXPECT_EQ(ids.count("climber/l_sole-env/floor") + ids.count("climber/r_sole-env/floor"), 0u)
        << "step " << i;
    for (const std::string& id : ids) {
      if (id.rfind("supporter/", 0) == 0 && id.find("-climber/") != std::string::npos) {
        EXPECT_TRUE(id == kLeftPalm || id == kRightPalm) << "step " << i << ": " << id;
      }
    }
    const bool on_left = ids.count(kLeftPalm) == 1, on_right = ids.count(kRightPalm) == 1;
    left.see(on_left);
    right.see(on_right);
    // On one palm alone (no sole on a platform, not on the other palm): that hand carries the
    // climber's whole weight and the supporter's feet carry both robots.
    const bool on_platform =
        ids.count("climber/l_sole-env/platform_a") || ids.count("climber/r_sole-env/platform_a") ||
        ids.count("climber/l_sole-env/platform_b") || ids.count("climber/r_sole-env/platform_b");
    if (on_left != on_right && !on_platform) {
      ++alone_on_a_palm;
      EXPECT_NEAR(vertical_support(steps[i], climber), m_climber * g, 1e-3 * m_climber * g) << i;
      double feet_z = 0.0;
      for (const VertexForce& f : steps[i].forces)
        if (steps[i].contacts[f.contact].contact.s2.entity == env) feet_z += f.force_W.z();
      EXPECT_NEAR(feet_z, (m_climber + m_supporter) * g, 1e-3 * (m_climber + m_supporter) * g) << i;
    }
  }
  EXPECT_TRUE(left.made) << "the climber's left sole never lands on the left palm";
  EXPECT_TRUE(left.broken) << "the climber's left sole never leaves the left palm";
  EXPECT_TRUE(right.made) << "the climber's right sole never lands on the right palm";
  EXPECT_TRUE(right.broken) << "the climber's right sole never leaves the right palm";
  // Once on the left palm alone, once on the right palm alone.
  EXPECT_GE(alone_on_a_palm, 2) << "the climber never stands on one palm alone";
  // From both feet on A (x < -0.4 m) to both feet on B (x > 0.4 m).
  const auto last = test::stance_ids(scenario, steps.back().stance);
  EXPECT_EQ(
      last.count("climber/l_sole-env/platform_b") + last.count("climber/r_sole-env/platform_b"),
      2u);
  const int o = system.offset(climber);
  EXPECT_LT(steps.front().q[o], -0.4);
  EXPECT_GT(steps.back().q[o], 0.4);
  // The motion between the steps: every step moves (the swing foot around the platforms' edges
  // by the detour, planner/motion/stance_rrt.h) and certifies sample by sample.
  test::expect_motion_certified(scenario, result, "humanoid_climb_on_robot");
}

}  // namespace
}  // namespace stanceplan
