// A stance whose fixed placements put two links into each other: `posture` names the collision
// and both links whatever the margin; `plan` refuses the scenario before any search, naming the
// file, the two stance entries and the depth.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;
using ::testing::MatchesRegex;

// humanoid_stand.yaml with both soles fixed at the floor's origin (the feet inside each other),
// and `collision` appended when not empty.
std::string overlapping_soles(const std::string& name, const std::string& collision) {
  std::ifstream in(test::source_path("scenarios/humanoid_stand.yaml"));
  std::string text((std::istreambuf_iterator<char>(in)), {});
  text = std::regex_replace(text, std::regex("\\.\\./assets"), test::source_path("assets"));
  const std::string both =
      "    - {s1: robot/l_sole, s2: env/floor, placement: [0, 0, 0]}\n"
      "    - {s1: robot/r_sole, s2: env/floor, placement: [0, 0, 0]}";
  text = std::regex_replace(text,
                            std::regex("initial:\\n    - \\{s1: robot/l_sole, s2: env/floor\\}\\n"
                                       "    - \\{s1: robot/r_sole, s2: env/floor\\}"),
                            "initial:\n" + both);
  if (!collision.empty()) text += "collision: " + collision + "\n";
  const std::string path = (test::temp_dir("pinned") / name).string();
  std::ofstream(path) << text;
  return path;
}

void expect_posture_names_the_collision(const std::string& scenario) {
  const std::string out = (test::temp_dir("pinned") / "p.json").string();
  std::filesystem::remove(out);
  const test::CliResult r = test::run_cli({"posture", scenario, "--out", out});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("infeasible (collision: robot/l_foot (pinned by contact robot/l_sole"
                               " on env/floor) and robot/r_foot (pinned by contact robot/r_sole on"
                               " env/floor) are "));
  EXPECT_THAT(r.err, HasSubstr(" m into each other"));
  EXPECT_THAT(r.err, HasSubstr("\n  collision          worst violation 0.04"));
  // The guess is written to be looked at, marked failed: certify refuses it and says why.
  ASSERT_TRUE(std::filesystem::exists(out));
  const test::CliResult certified = test::run_cli({"certify", out});
  EXPECT_EQ(certified.code, 2);
  EXPECT_THAT(certified.err,
              HasSubstr("certification failed: solver status at step 0: the last iterate of a "
                        "failed solve (no posture for the initial stance: infeasible (collision: "
                        "robot/l_foot (pinned by contact robot/l_sole"));
}

TEST(PinnedCollision, PostureNamesBothLinksWithMarginZero) {
  expect_posture_names_the_collision(overlapping_soles("margin0.yaml", "{margin: 0}"));
}

TEST(PinnedCollision, PostureNamesBothLinksWithTheDefaultMargin) {
  expect_posture_names_the_collision(overlapping_soles("default.yaml", ""));
}

TEST(PinnedCollision, PlanRefusesTheScenarioWithFileContactsAndDepth) {
  const std::string scenario = overlapping_soles("plan.yaml", "");
  const std::string out = (test::temp_dir("pinned") / "plan.json").string();
  const test::CliResult r = test::run_cli({"plan", scenario, "--out", out});
  EXPECT_EQ(r.code, 1) << r.err;
  // Line 22: the second entry of stances.initial.
  EXPECT_THAT(
      r.err,
      MatchesRegex("stanceplan: error: " + std::regex_replace(scenario, std::regex("\\."), "\\.") +
                   ":22: stances\\.initial\\[1\\]: the fixed placements of "
                   "stances\\.initial\\[0\\] \\(robot/l_sole on env/floor\\) and "
                   "stances\\.initial\\[1\\] \\(robot/r_sole on env/floor\\) put "
                   "robot/l_foot and robot/r_foot 0\\.[0-9]{4} m into each other\n"));
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(PinnedCollision, FeetPlacedApartStillSolve) {
  // The same fixed placements 0.2 m apart: the new checks reject only what is wrong.
  std::string path = overlapping_soles("apart.yaml", "");
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  text = std::regex_replace(text, std::regex("r_sole, s2: env/floor, placement: \\[0, 0, 0\\]"),
                            "r_sole, s2: env/floor, placement: [0, -0.2, 0]");
  std::ofstream(path) << text;
  const test::CliResult r =
      test::run_cli({"posture", path, "--out", (test::temp_dir("pinned") / "a.json").string()});
  EXPECT_EQ(r.code, 0) << r.err;
}

}  // namespace
}  // namespace stanceplan
