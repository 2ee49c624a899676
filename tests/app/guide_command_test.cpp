// `stanceplan guide` and the computed guide in `plan` (app/guide_command.h,
// app/pipeline_guide.cpp): the guide written is the guide used (pasted into the file it gives the
// same milestones), and a failing stage is named with exit 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/pipeline.h"
#include "planner/util/text_file.h"
#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

TEST(GuideCommand, WritesAGuideThatPastedIntoTheScenarioGivesTheSameMilestones) {
  const std::string file = test::source_path("scenarios/guide_free/side_step.yaml");
  const std::string out = (test::temp_dir("guide") / "side_step_guide.yaml").string();
  const test::CliResult r = test::run_cli({"guide", file, "--out", out});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = read_text_file(out);
  EXPECT_EQ(text.rfind("# computed by stanceplan guide (seed 1): ", 0), 0u) << text;
  EXPECT_NE(text.find("\nguide:\n  - robot: {base_position: ["), std::string::npos) << text;

  Scenario computed = load_scenario(file);
  ASSERT_TRUE(complete_scenario_guide(computed).has_value());
  const std::string pasted = (test::temp_dir("guide") / "side_step_pasted.yaml").string();
  std::ofstream(pasted) << replace_all(read_text_file(file), "../../assets/",
                                       test::source_path("assets") + "/")
                        << text;
  const Scenario read = load_scenario(pasted);
  ASSERT_TRUE(read.has_guide);
  ASSERT_EQ(read.milestones.size(), computed.milestones.size());
  for (size_t i = 0; i < read.milestones.size(); ++i) {
    EXPECT_EQ(read.milestones[i], computed.milestones[i]) << "milestone " << i;
    EXPECT_EQ(read.milestone_masks[i], computed.milestone_masks[i]) << "milestone " << i;
  }
}

// The seed is the guide's only source of randomness: the same seed, the same text.
TEST(GuideCommand, TheSameSeedWritesTheSameGuide) {
  const std::string file = test::source_path("scenarios/guide_free/stairs.yaml");
  const test::CliResult a = test::run_cli({"guide", file, "--seed", "7"});
  const test::CliResult b = test::run_cli({"guide", file, "--seed", "7"});
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(a.out.rfind("# computed by stanceplan guide (seed 7): ", 0), 0u) << a.out;
  EXPECT_EQ(a.out, b.out);
}

TEST(GuideCommand, AGoalStanceWithoutPostureExitsTwoNamingTheStage) {
  const test::CliResult r =
      test::run_cli({"plan", test::source_path("tests/data/guide/feet_apart.yaml"), "--out",
                     (test::temp_dir("guide") / "feet_apart.json").string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("stanceplan: no plan: guide: goal posture: no posture for the goal stance "
                       "of "),
            std::string::npos)
      << r.err;
}

TEST(GuideCommand, NoCollisionFreePathWithinTheBudgetExitsTwoNamingTheStage) {
  const test::CliResult r =
      test::run_cli({"guide", test::source_path("tests/data/guide/behind_wall.yaml")});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("stanceplan: guide: path: no collision-free path from the initial to the "
                       "goal configuration within 20000 validity checks"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace stanceplan
