// The computed self-collision matrix through the program: `stanceplan inspect --collision-matrix`
// (its exact lines, JSON and SRDF file), and a scenario whose robot has overlapping collision
// boxes and no SRDF, which has no posture without the matrix and plans with it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "planner/io/scenario.h"
#include "planner/solver/posture_solver.h"
#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

std::string data(const std::string& name) {
  return test::source_path("tests/data/collision_matrix/" + name);
}

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(InspectCollisionMatrix, PrintsThePairsAndWritesThemAsSrdf) {
  const std::string srdf = (test::temp_dir("collision_matrix") / "arm.srdf").string();
  std::filesystem::remove(srdf);
  const test::CliResult r = test::run_cli(
      {"inspect", data("two_finger_arm.urdf"), "--collision-matrix", "--srdf-out", srdf});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out,
            "self-collision matrix of two_finger_arm: 9 pairs disabled (6 adjacent, 3 always in "
            "collision over 1000 samples, seed 0)\n"
            "  base / turret: adjacent\n"
            "  turret / upper_arm: adjacent\n"
            "  upper_arm / forearm: adjacent\n"
            "  forearm / palm: adjacent\n"
            "  palm / finger_1_base: always (1000 of 1000 samples)\n"
            "  palm / finger_2_base: always (1000 of 1000 samples)\n"
            "  finger_1_base / finger_1_tip: adjacent\n"
            "  finger_1_base / finger_2_base: always (1000 of 1000 samples)\n"
            "  finger_2_base / finger_2_tip: adjacent\n"
            "wrote " +
                srdf + "\n");
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(read(srdf),
            "<?xml version=\"1.0\"?>\n"
            "<!-- Self-collision matrix computed by stanceplan (6 adjacent, 3 always in collision "
            "over 1000 samples, seed 0). -->\n"
            "<robot name=\"two_finger_arm\">\n"
            "  <disable_collisions link1=\"base\" link2=\"turret\" reason=\"Adjacent\"/>\n"
            "  <disable_collisions link1=\"turret\" link2=\"upper_arm\" reason=\"Adjacent\"/>\n"
            "  <disable_collisions link1=\"upper_arm\" link2=\"forearm\" reason=\"Adjacent\"/>\n"
            "  <disable_collisions link1=\"forearm\" link2=\"palm\" reason=\"Adjacent\"/>\n"
            "  <disable_collisions link1=\"palm\" link2=\"finger_1_base\" reason=\"Always\"/>\n"
            "  <disable_collisions link1=\"palm\" link2=\"finger_2_base\" reason=\"Always\"/>\n"
            "  <disable_collisions link1=\"finger_1_base\" link2=\"finger_1_tip\" "
            "reason=\"Adjacent\"/>\n"
            "  <disable_collisions link1=\"finger_1_base\" link2=\"finger_2_base\" "
            "reason=\"Always\"/>\n"
            "  <disable_collisions link1=\"finger_2_base\" link2=\"finger_2_tip\" "
            "reason=\"Adjacent\"/>\n"
            "</robot>\n");
  // The file is an SRDF the inspect command itself reads back: the three sampled pairs are gone.
  const test::CliResult back =
      test::run_cli({"inspect", data("two_finger_arm.urdf"), "--srdf", srdf, "--json"});
  ASSERT_EQ(back.code, 0) << back.err;
  EXPECT_EQ(nlohmann::json::parse(back.out)["collision"]["srdf_disabled_pairs"], 3);
}

TEST(InspectCollisionMatrix, JsonSamplesSeedAndNever) {
  const test::CliResult r = test::run_cli({"inspect", data("slider.urdf"), "--collision-matrix",
                                           "--samples", "200", "--seed", "3", "--never", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto d = nlohmann::json::parse(r.out);
  EXPECT_EQ(d["robot"], "slider");
  EXPECT_EQ(d["samples"], 200);
  EXPECT_EQ(d["seed"], 3);
  ASSERT_EQ(d["pairs"].size(), 1u);
  EXPECT_EQ(d["pairs"][0],
            nlohmann::json(
                {{"link1", "bar"}, {"link2", "ball"}, {"reason", "default"}, {"collisions", 195}}));
}

TEST(InspectCollisionMatrix, OptionsWithoutTheFlagOrWithAnSrdfAreUsageErrors) {
  const test::CliResult alone =
      test::run_cli({"inspect", data("two_finger_arm.urdf"), "--srdf-out", "x.srdf"});
  EXPECT_EQ(alone.code, 1);
  EXPECT_THAT(alone.err, HasSubstr("stanceplan: --srdf-out requires --collision-matrix"));
  const test::CliResult both = test::run_cli(
      {"inspect", data("two_finger_arm.urdf"), "--collision-matrix", "--srdf", "x.srdf"});
  EXPECT_EQ(both.code, 1);
  EXPECT_THAT(both.err, HasSubstr("stanceplan: --srdf excludes --collision-matrix"));
  const test::CliResult zero = test::run_cli(
      {"inspect", data("two_finger_arm.urdf"), "--collision-matrix", "--samples", "0"});
  EXPECT_EQ(zero.code, 1);
  EXPECT_THAT(zero.err, HasSubstr("--samples: expected a whole number from 1 to 10000000, "
                                  "found \"0\""));
}

TEST(ComputedCollisionMatrix, WithoutItTheOverlappingRobotHasNoPostureForCollision) {
  Scenario scenario = load_scenario(data("tap_pads.yaml"));
  SceneSpec spec = scenario.spec;
  spec.collision_matrix.reset();  // as before the matrix existed
  scenario.scene = build_scene(spec);
  SolverOptions options = scenario.solver;
  options.diagnose_infeasibility = true;
  const PostureSolver solver(scenario.scene, options);
  const PostureResult result = solver.solve(
      scenario.loaded_request(scenario.initial_stance, scenario.initial_configuration));
  EXPECT_NE(result.status, PostureStatus::Solved);
  EXPECT_EQ(result.blocking_family, "collision");
}

TEST(ComputedCollisionMatrix, TheOverlappingRobotPlansWithoutAnIgnoreListAndSaysWhy) {
  const std::string out = (test::temp_dir("collision_matrix") / "tap_pads.json").string();
  const test::CliResult r =
      test::run_cli({"plan", data("tap_pads.yaml"), "--out", out, "--threads", "1"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("stanceplan: robot: 9 self-collision pairs disabled (computed: 6 "
                               "adjacent, 3 always in collision over 1000 samples, seed 0); write "
                               "them with stanceplan inspect --collision-matrix --srdf-out "
                               "FILE\n"));
  const auto plan = nlohmann::json::parse(read(out));
  EXPECT_EQ(plan["steps"].size(), 3u);
  int computed = 0;
  for (const auto& reason : plan["collision_pairs_ignored_reasons"])
    computed += reason == "computed (always)";
  EXPECT_EQ(computed, 3);
  const test::CliResult certified = test::run_cli({"certify", out});
  EXPECT_EQ(certified.code, 0) << certified.out << certified.err;
}

}  // namespace
}  // namespace stanceplan
