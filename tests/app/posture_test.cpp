// `stanceplan posture`: a solved stance is written as a one-step plan whose forces balance the
// weight; a stance without a posture exits 2 and names the violated family.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

TEST(PostureCommand, HumanoidStandSolvesAndTheForcesBalanceTheWeight) {
  const std::string out = (test::temp_dir("posture") / "p.json").string();
  const test::CliResult r =
      test::run_cli({"posture", test::source_path("scenarios/humanoid_stand.yaml"), "--out", out});
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(out);
  const auto plan = nlohmann::json::parse(in);
  EXPECT_EQ(plan["format"], "stanceplan/plan@1");
  ASSERT_EQ(plan["steps"].size(), 1u);
  double fz = 0.0;
  for (const auto& f : plan["steps"][0]["forces"]) fz += f["force_world"][2].get<double>();
  const double weight = 58.34 * 9.81;  // assets/README.md: 58.34 kg
  EXPECT_NEAR(fz / weight, 1.0, 1e-3);
  EXPECT_EQ(plan["steps"][0]["forces"].size(), 8u);
  EXPECT_EQ(test::run_cli({"certify", out}).code, 0);
}

TEST(PostureCommand, FeetHeldThreeMetresApartHaveNoPostureAndExitTwo) {
  std::ifstream in(test::source_path("scenarios/humanoid_stand.yaml"));
  std::string text((std::istreambuf_iterator<char>(in)), {});
  text = std::regex_replace(text, std::regex("\\.\\./assets"), test::source_path("assets"));
  text = std::regex_replace(
      text,
      std::regex("initial:\\n    - \\{s1: robot/l_sole, s2: env/floor\\}\\n    - \\{s1: "
                 "robot/r_sole, s2: env/floor\\}"),
      "initial:\n    - {s1: robot/l_sole, s2: env/floor, placement: [-3.0, 0, 0]}\n"
      "    - {s1: robot/r_sole, s2: env/floor, placement: [0.0, 0, 0]}");
  const std::string path = (test::temp_dir("posture") / "split.yaml").string();
  std::ofstream(path) << text;
  const std::string out = (test::temp_dir("posture") / "split.json").string();
  std::filesystem::remove(out);
  const test::CliResult r = test::run_cli({"posture", path, "--out", out});
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, HasSubstr("stanceplan: no posture for the initial stance of"));
  // The contact family is blamed with its contact named.
  EXPECT_THAT(r.err, HasSubstr("worst violated family: contact_geometry at contact robot/"));
  // The last iterate is written, marked failed, and can be rendered; certify refuses it.
  EXPECT_THAT(r.err, HasSubstr("wrote the last iterate of the failed solve to " + out));
  std::ifstream in_plan(out);
  ASSERT_TRUE(in_plan.good());
  const auto plan = nlohmann::json::parse(in_plan);
  EXPECT_THAT(plan["failed"]["reason"].get<std::string>(),
              HasSubstr("no posture for the initial stance: "));
  ASSERT_EQ(plan["steps"].size(), 1u);
  EXPECT_NE(plan["steps"][0]["solver"]["status"], "solved");
  const test::CliResult certified = test::run_cli({"certify", out});
  EXPECT_EQ(certified.code, 2);
  EXPECT_THAT(certified.err,
              HasSubstr("certification failed: solver status at step 0: the last iterate of a "
                        "failed solve ("));
  const std::string image_dir = (test::temp_dir("posture") / "split_images").string();
  const test::CliResult rendered = test::run_cli({"render", out, "--out", image_dir});
  EXPECT_EQ(rendered.code, 0) << rendered.err;
  EXPECT_TRUE(std::filesystem::exists(image_dir + "/step_000.png"));
}

TEST(PostureCommand, AReadPlanKeepsEachStepsSolverStatusAndRefusesAnUnknownOne) {
  const std::string out = (test::temp_dir("posture") / "stand.json").string();
  ASSERT_EQ(
      test::run_cli({"posture", test::source_path("scenarios/humanoid_stand.yaml"), "--out", out})
          .code,
      0);
  std::ifstream in(out);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  const std::string bad = (test::temp_dir("posture") / "bad_status.json").string();
  std::ofstream(bad) << std::regex_replace(text, std::regex("\"status\": *\"solved\""),
                                           "\"status\": \"fine\"");
  const test::CliResult r = test::run_cli({"certify", bad});
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr(bad + ": steps[0].solver.status: expected solved, infeasible, "
                                     "iteration_limit or numerical_failure, found \"fine\""));
}

}  // namespace
}  // namespace stanceplan
