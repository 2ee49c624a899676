// The paper's fourth scenario (docs/METHOD.md section 5), planned within its own budget and
// certified: scenarios/two_humanoids_table.yaml, two humanoids carry a table with four fixed
// bilateral grasps.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "planner/search/stance_search.h"
#include "tests/support/paths.h"
#include "tests/support/planned_scenario.h"
#include "tests/support/scenario_motion.h"

namespace stanceplan {
namespace {

// Plans with the scenario's own options (budgets included) and certifies the plan; then the carry.
TEST(TableCarryPlan, PlansCertifiesTheHandsNeverLetGoAndTheFeetWalkTheTable1Point5Metres) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/two_humanoids_table.yaml"));
  const SearchResult result = StanceSearch(scenario, scenario.search).run();
  test::expect_certified(scenario, result, "two_humanoids_table");
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  const auto& steps = result.plan.steps;
  const std::vector<std::string> hands = {
      "r1/l_palm-table/handle_back_left", "r1/r_palm-table/handle_back_right",
      "r2/l_palm-table/handle_front_right", "r2/r_palm-table/handle_front_left"};
  std::set<std::string> moved;
  for (size_t i = 0; i < steps.size(); ++i) {
    const auto ids = test::stance_ids(scenario, steps[i].stance);
    for (const std::string& h : hands) EXPECT_EQ(ids.count(h), 1u) << "step " << i << ": " << h;
    for (const Contact& c : steps[i].stance.contacts())
      if (c.s2.entity == scenario.scene.system.find_entity("table")) {
        EXPECT_TRUE(c.bilateral) << "step " << i;
        EXPECT_TRUE(c.fixed) << "step " << i;
      }
    // Each robot keeps a foot on the floor (the table is no stretcher).
    EXPECT_TRUE(ids.count("r1/l_sole-env/floor") || ids.count("r1/r_sole-env/floor"))
        << "step " << i;
    EXPECT_TRUE(ids.count("r2/l_sole-env/floor") || ids.count("r2/r_sole-env/floor"))
        << "step " << i;
    if (i > 0) {
      ASSERT_TRUE(steps[i].changed.has_value());
      moved.insert(scenario.scene.surfaces.id(scenario.scene.system, steps[i].changed->s1));
    }
  }
  EXPECT_EQ(moved, (std::set<std::string>{"r1/l_sole", "r1/r_sole", "r2/l_sole", "r2/r_sole"}));
  const System& system = scenario.scene.system;
  for (const char* name : {"r1", "r2", "table"}) {
    const int o = system.offset(system.find_entity(name));
    EXPECT_NEAR(steps.back().q[o] - steps.front().q[o], 1.5, 0.1) << name;
  }
  // The motion between the steps: every step moves and certifies sample by sample.
  test::expect_motion_certified(scenario, result, "two_humanoids_table");
}

}  // namespace
}  // namespace stanceplan
