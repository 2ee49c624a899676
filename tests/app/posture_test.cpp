// `stanceplan posture`: a solved stance is written as a one-step plan whose forces balance the
// weight; a stance without a posture exits 2 and names the violated family.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

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
  const test::CliResult r = test::run_cli(
      {"posture", path, "--out", (test::temp_dir("posture") / "split.json").string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, HasSubstr("stanceplan: no posture for the initial stance of"));
  EXPECT_THAT(r.err, HasSubstr("worst violated family: contact_geometry"));
}

}  // namespace
}  // namespace stanceplan
