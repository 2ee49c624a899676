// Whole plans on extracted environment surfaces (`surfaces: auto`, planner/contact/affordances.h):
// the walk and the untuned stairs with their environment's surface file replaced by extraction
// (tests/data/affordances/), and the mesh-only staircase (assets/environments/mesh_stairs, one STL
// file for the steps and the platform). Each plan is certified through its file, as `stanceplan
// certify` does: the plan repeats every surface it uses, so nothing else is needed. Counts, never
// wall time; one solver process, so they are deterministic.
#include <gtest/gtest.h>

#include "planner/search/stance_search.h"
#include "tests/support/paths.h"
#include "tests/support/planned_scenario.h"

namespace stanceplan {
namespace {

using test::plan_with_one_process;

std::string contacts_of(const Scenario& scenario, const PlanStep& step) {
  std::string out;
  for (const std::string& id : test::stance_ids(scenario, step.stance)) out += id + " ";
  return out;
}

// The extracted floor is the file's floor (same polygon and frame): the same plan, step by step,
// with env/floor named env/support_0 (the vertex order differs, so the solves differ in rounding).
TEST(ExtractedSurfaces, TheWalkOnTheExtractedFloorIsTheWalkOnTheFilesFloor) {
  const Scenario file = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  const Scenario extracted =
      load_scenario(test::source_path("tests/data/affordances/humanoid_walk_auto.yaml"));
  const SearchResult a = plan_with_one_process(file);
  const SearchResult b = plan_with_one_process(extracted);
  test::expect_certified(extracted, b, "extracted_walk");
  ASSERT_EQ(a.status, PlanStatus::Found) << a.message;
  ASSERT_EQ(b.status, PlanStatus::Found) << b.message;
  ASSERT_EQ(a.plan.steps.size(), b.plan.steps.size());
  for (size_t i = 0; i < a.plan.steps.size(); ++i) {
    std::string expected = contacts_of(file, a.plan.steps[i]);
    for (size_t at; (at = expected.find("env/floor")) != std::string::npos;)
      expected.replace(at, 9, "env/support_0");
    EXPECT_EQ(contacts_of(extracted, b.plan.steps[i]), expected) << "step " << i;
    EXPECT_LE((a.plan.steps[i].q - b.plan.steps[i].q).lpNorm<Eigen::Infinity>(), 1e-3)
        << "step " << i;
  }
}

// The untuned stairs on extracted surfaces: both soles on the landing (support_5) at the end;
// 138 solver calls were measured, as many as with the surface file.
TEST(ExtractedSurfaces, TheUntunedStairsPlanOnExtractedTreads) {
  const Scenario scenario =
      load_scenario(test::source_path("tests/data/affordances/stairs_auto.yaml"));
  const SearchResult result = plan_with_one_process(scenario);
  test::expect_certified(scenario, result, "extracted_stairs");
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  EXPECT_EQ(contacts_of(scenario, result.plan.steps.back()),
            "robot/l_sole-env/support_5 robot/r_sole-env/support_5 ");
  EXPECT_LE(result.solver_calls, 138);
}

// The mesh-only staircase: the treads and the platform come from one STL file; 109 solver calls
// and 13 steps were measured.
TEST(ExtractedSurfaces, TheHumanoidClimbsTheMeshStaircase) {
  const Scenario scenario =
      load_scenario(test::source_path("tests/data/affordances/mesh_stairs.yaml"));
  const SearchResult result = plan_with_one_process(scenario);
  test::expect_certified(scenario, result, "mesh_stairs");
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  EXPECT_EQ(contacts_of(scenario, result.plan.steps.back()),
            "robot/l_sole-env/support_5 robot/r_sole-env/support_5 ");
  EXPECT_LE(result.solver_calls, 109);
}

}  // namespace
}  // namespace stanceplan
