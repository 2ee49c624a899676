// `stanceplan motion PLAN.json` (app/motion_command.h): adds the motion to a plan file without
// one, certified; writes the trajectory CSV; `render --gif` then plays the motion.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "planner/io/plan_writer.h"
#include "planner/util/atomic_file.h"
#include "planner/util/text_file.h"
#include "tests/support/cli.h"
#include "tests/support/forward_step.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

TEST(MotionCommand, AddsTheCertifiedMotionToAPlanFileAndExportsItAndPlaysIt) {
  const test::ForwardStep fs = test::forward_step_plan();
  const fs::path dir = test::temp_dir("motion_command");
  const std::string plan = (dir / "plan.json").string(), moved = (dir / "moved.json").string();
  write_plan(fs.plan, fs.scenario, plan);
  nlohmann::json original = nlohmann::json::parse(read_text_file(plan));
  original["cone_generators"] = 3;  // not the default: the rewritten plan must keep it
  write_file_atomically(plan, original.dump(1));
  ASSERT_TRUE(original["entities"][0].contains("surfaces_file"));
  const test::CliResult r =
      test::run_cli({"motion", plan, "--out", moved, "--csv", (dir / "csv").string(), "--stats"});
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("motion: 2 steps, "));
  // --stats: a line per step, each into a step of the plan (1 and 2), none beyond.
  EXPECT_THAT(r.out, ::testing::ContainsRegex("stats: motion into step 1: [0-9.]+ ms, [1-9][0-9]* "
                                              "solves \\([0-9]+ iterations\\), [0-9]+ samples, "
                                              "solved"));
  EXPECT_THAT(r.out, HasSubstr("stats: motion into step 2: "));
  EXPECT_THAT(r.out, ::testing::Not(HasSubstr("stats: motion into step 3")));
  EXPECT_THAT(r.out, HasSubstr("wrote " + moved + " (certified, with motion)"));
  const nlohmann::json rewritten = nlohmann::json::parse(read_text_file(moved));
  EXPECT_EQ(rewritten["format"], "stanceplan/plan@2");
  // What the plan says of its world is kept: each entity's surface file, the cone's generators.
  EXPECT_EQ(rewritten["cone_generators"], 3);
  for (size_t e = 0; e < original["entities"].size(); ++e)
    EXPECT_EQ(rewritten["entities"][e].value("surfaces_file", ""),
              original["entities"][e].value("surfaces_file", ""))
        << "entity " << e;
  EXPECT_TRUE(fs::exists(dir / "csv" / "robot.csv"));
  EXPECT_EQ(test::run_cli({"certify", moved}).code, 0);
  const test::CliResult gif =
      test::run_cli({"render", moved, "--gif", (dir / "moved.gif").string(), "--size", "160x90"});
  ASSERT_EQ(gif.code, 0) << gif.err;
  EXPECT_THAT(gif.out, HasSubstr("render: animated GIF of "));
  EXPECT_THAT(gif.out, ::testing::Not(HasSubstr("GIF of 3 frames")));  // samples between steps
}

}  // namespace
}  // namespace stanceplan
