// TALOS as published (../shared/robots/talos: URDF, meshes, SRDF) walks 1 m forward on the
// project's flat floor: tests/data/talos/talos_walk.yaml, the file a user runs
// (`stanceplan plan tests/data/talos/talos_walk.yaml`), with its SRDF's half_sitting posture to
// start from, the sole surfaces of tests/data/talos/, the search at its defaults with the soles as
// the only contact family and a base-position guide every 0.5 m. The plan must be found and
// certified through its file. Counts, never wall time: with one solver process the solver calls
// are deterministic (measured: 9 steps, 11 calls, within 2 a step).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "planner/search/stance_search.h"
#include "tests/support/paths.h"
#include "tests/support/planned_scenario.h"

namespace stanceplan {
namespace {

namespace fs = std::filesystem;

fs::path scenario_dir() {
  return test::source_path("tests/data/talos");
}

// Where the file's relative paths reach the shared models: ../shared beside the checkout.
fs::path shared_beside_checkout() {
  return (scenario_dir() / "../../../../shared").lexically_normal();
}

// A path of the file (relative to its folder) relative to ../shared beside the checkout, or
// nothing when it lies outside.
std::optional<fs::path> in_shared(const std::string& path_in_file) {
  const fs::path path = (scenario_dir() / path_in_file).lexically_normal();
  const fs::path relative = path.lexically_relative(shared_beside_checkout());
  if (relative.empty() || *relative.begin() == "..") return std::nullopt;
  return relative;
}

// Calls `visit` on every path field of the scenario's entities (urdf, srdf, surfaces and each
// package_paths entry), which may assign a new value to it.
void for_each_path(YAML::Node& root, const std::function<void(YAML::Node)>& visit) {
  for (YAML::Node entity : root["entities"]) {
    for (const char* key : {"urdf", "srdf", "surfaces"})
      if (entity[key]) visit(entity[key]);
    if (entity["package_paths"])
      for (YAML::Node dir : entity["package_paths"]) visit(dir);
  }
}

// The file as it is when STANCEPLAN_SHARED_DIR is unset (or names ../shared beside the checkout);
// otherwise a copy in a temporary folder with every path made absolute, those under ../shared
// moved under STANCEPLAN_SHARED_DIR.
std::string talos_walk_scenario() {
  const fs::path file = scenario_dir() / "talos_walk.yaml";
  const fs::path shared = fs::path(test::shared_dir()).lexically_normal();
  if (shared == shared_beside_checkout()) return file.string();
  YAML::Node root = YAML::LoadFile(file.string());
  for_each_path(root, [&](YAML::Node value) {
    const std::string path = value.as<std::string>();
    const std::optional<fs::path> relative = in_shared(path);
    value = (relative ? shared / *relative : (scenario_dir() / path).lexically_normal()).string();
  });
  const std::string copy = (test::temp_dir("talos_walk") / "talos_walk.yaml").string();
  YAML::Emitter out;
  out << root;
  std::ofstream(copy) << out.c_str() << "\n";
  return copy;
}

// The file a user runs: every path is relative to its folder; the robot's reach ../shared beside
// the checkout, the others stay in the repository. Reads the file only: runs without ../shared.
TEST(TalosWalk, FilePathsAreRelativeToItsFolder) {
  YAML::Node root = YAML::LoadFile((scenario_dir() / "talos_walk.yaml").string());
  std::vector<std::string> shared_paths;
  for_each_path(root, [&](YAML::Node value) {
    const std::string path = value.as<std::string>();
    EXPECT_TRUE(fs::path(path).is_relative()) << path;
    if (const std::optional<fs::path> relative = in_shared(path))
      shared_paths.push_back(relative->string());
    else
      EXPECT_TRUE(fs::exists(scenario_dir() / path)) << path;
  });
  const std::vector<std::string> expected = {
      "robots/talos/robots/talos_data/robots/talos_reduced.urdf",
      "robots/talos/robots/talos_data/srdf/talos.srdf", "robots/talos"};
  EXPECT_EQ(shared_paths, expected);
  EXPECT_EQ(shared_beside_checkout(), fs::path(STANCEPLAN_SHARED_DIR).lexically_normal());
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
