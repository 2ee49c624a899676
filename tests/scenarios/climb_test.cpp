// Issue 7, scenario 5: scenarios/humanoid_climb_on_robot.yaml, planned within its own budget and
// certified. A humanoid crosses the gap between two platforms by stepping on the raised forearm of
// a second humanoid standing on the floor in the gap.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "planner/search/stance_search.h"
#include "tests/support/paths.h"
#include "tests/support/planned_scenario.h"

namespace stanceplan {
namespace {

const std::string kForearm = "supporter/l_forearm-climber/l_sole";

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

TEST(ClimbOnRobotPlan, PlansCertifiesAndTheClimberCrossesOnTheSupportersForearm) {
  const Scenario scenario =
      load_scenario(test::source_path("scenarios/humanoid_climb_on_robot.yaml"));
  const SearchResult result = StanceSearch(scenario, scenario.search).run();
  test::expect_certified(scenario, result, "humanoid_climb_on_robot");
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;

  const System& system = scenario.scene.system;
  const int climber = system.find_entity("climber");
  const int supporter = system.find_entity("supporter");
  const double g = 9.81;
  const double m_climber = system.entity(climber).model->total_mass;
  const double m_supporter = system.entity(supporter).model->total_mass;
  const auto& steps = result.plan.steps;
  bool made = false, broken = false, alone_on_forearm = false;
  for (size_t i = 0; i < steps.size(); ++i) {
    const auto ids = test::stance_ids(scenario, steps[i].stance);
    // The supporter's feet never move and the climber never touches the floor.
    EXPECT_EQ(ids.count("supporter/l_sole-env/floor"), 1u) << "step " << i;
    EXPECT_EQ(ids.count("supporter/r_sole-env/floor"), 1u) << "step " << i;
    EXPECT_EQ(ids.count("climber/l_sole-env/floor") + ids.count("climber/r_sole-env/floor"), 0u)
        << "step " << i;
    const bool on_forearm = ids.count(kForearm) == 1;
    if (on_forearm && !made) made = true;
    if (!on_forearm && made) broken = true;
    // Standing on the forearm alone (no sole on a platform): the forearm carries the climber's
    // whole weight and the supporter's feet carry both robots.
    const bool on_platform =
        ids.count("climber/l_sole-env/platform_a") || ids.count("climber/r_sole-env/platform_a") ||
        ids.count("climber/l_sole-env/platform_b") || ids.count("climber/r_sole-env/platform_b");
    if (on_forearm && !on_platform) {
      alone_on_forearm = true;
      EXPECT_NEAR(vertical_support(steps[i], climber), m_climber * g, 1e-3 * m_climber * g) << i;
      double feet_z = 0.0;
      for (const VertexForce& f : steps[i].forces)
        if (steps[i].contacts[f.contact].contact.s2.entity == system.find_entity("env"))
          feet_z += f.force_W.z();
      EXPECT_NEAR(feet_z, (m_climber + m_supporter) * g, 1e-3 * (m_climber + m_supporter) * g) << i;
    }
  }
  EXPECT_TRUE(made) << "the climber's sole never lands on the forearm";
  EXPECT_TRUE(broken) << "the climber's sole never leaves the forearm";
  EXPECT_TRUE(alone_on_forearm) << "the climber never stands on the forearm alone";
  // From both feet on A (x < -0.45 m) to both feet on B (x > 0.45 m).
  const auto last = test::stance_ids(scenario, steps.back().stance);
  EXPECT_EQ(
      last.count("climber/l_sole-env/platform_b") + last.count("climber/r_sole-env/platform_b"),
      2u);
  const int o = system.offset(climber);
  EXPECT_LT(steps.front().q[o], -0.45);
  EXPECT_GT(steps.back().q[o], 0.45);
}

}  // namespace
}  // namespace stanceplan
