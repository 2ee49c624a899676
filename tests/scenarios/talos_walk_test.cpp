// TALOS as published (../shared/robots/talos: URDF, meshes, SRDF) walks 1 m forward on the
// project's flat floor: its SRDF's half_sitting posture to start from, the sole surfaces of
// tests/data/talos/, the search at its defaults with the soles as the only contact family and a
// base-position guide every 0.5 m. The plan must be found and certified through its file. Counts,
// never wall time: with one solver process the solver calls are deterministic (measured: 9 steps,
// 11 calls, within 2 a step).
#include <gtest/gtest.h>

#include <fstream>

#include "planner/search/stance_search.h"
#include "tests/support/paths.h"
#include "tests/support/planned_scenario.h"

namespace stanceplan {
namespace {

// The scenario, with absolute paths to ../shared and to the project's files. Placements are in the
// floor's surface frame, centred at x = 1.5 m; at half_sitting the sole centroids are 1.4 cm
// behind the base and 8.5 cm to each side.
std::string talos_walk_scenario() {
  const std::string talos = test::shared_path("robots/talos");
  const std::string floor = test::source_path("assets/environments/flat_ground/flat_ground");
  const std::string path = (test::temp_dir("talos_walk") / "talos_walk.yaml").string();
  std::ofstream(path) << "format: stanceplan/scenario@1\n"
                         "name: talos_walk\n"
                         "entities:\n"
                         "  - name: talos\n"
                         "    kind: floating\n"
                         "    urdf: " +
                             test::talos_urdf() + "\n    package_paths: [" + talos +
                             "]\n    srdf: " + talos +
                             "/robots/talos_data/srdf/talos.srdf\n    surfaces: " +
                             test::source_path("tests/data/talos/talos.surfaces.yaml") +
                             "\n    configuration: {srdf_state: half_sitting}\n"
                             "  - name: env\n    kind: environment\n    urdf: " +
                             floor + ".urdf\n    surfaces: " + floor +
                             ".surfaces.yaml\n"
                             "stances:\n"
                             "  initial:\n"
                             "    - {s1: talos/l_sole, s2: env/floor, placement: [-1.514, 0.085, "
                             "0]}\n"
                             "    - {s1: talos/r_sole, s2: env/floor, placement: [-1.514, -0.085, "
                             "0]}\n"
                             "  goal:\n"
                             "    - {s1: talos/l_sole, s2: env/floor, placement: [-0.514, 0.085, "
                             "0]}\n"
                             "    - {s1: talos/r_sole, s2: env/floor, placement: [-0.514, -0.085, "
                             "0]}\n"
                             "guide:\n"
                             "  - talos: {base_position: [0.5, 0, 1.02]}\n"
                             "  - talos: {base_position: [1.0, 0, 1.02]}\n"
                             "search:\n"
                             "  contact_pairs:\n"
                             "    - [talos/*_sole, env/floor]\n";
  return path;
}

TEST(TalosWalk, HalfSittingWalksOneMetreAndCertifies) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  const Scenario scenario = load_scenario(talos_walk_scenario());
  SearchOptions options = scenario.search;
  options.threads = 1;
  const SearchResult result = StanceSearch(scenario, options).run();
  test::expect_certified(scenario, result, "talos_walk");
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  const int steps = static_cast<int>(result.plan.steps.size());
  // Both feet move 1 m: each leaves the floor and comes back at least once after the start.
  EXPECT_GE(steps, 1 + 2 * 2);
  EXPECT_LE(result.solver_calls, 2 * steps);
  // The last posture stands 1 m ahead: its base over the goal's feet.
  EXPECT_NEAR(result.plan.steps.back().q[0], 1.0, 0.05);
}

}  // namespace
}  // namespace stanceplan
