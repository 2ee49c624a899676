// Limit cases of scenarios: an empty stance, a contact between two surfaces of one link, a surface
// used twice in one stance, a goal equal to the start and a guide path of one milestone. Each is
// either a clear error (file, line, field, expected, found) or a correct trivial plan.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "planner/io/plan_reader.h"
#include "planner/io/scenario.h"
#include "planner/util/input_error.h"
#include "tests/support/cli.h"
#include "tests/support/paths.h"
#include "tests/support/scenario_text.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

// The humanoid standing on `environment`, lines 1-13; stances and the rest follow.
std::string entities(const std::string& environment) {
  return test::humanoid_on(environment,
                           "{l_hip_p: -0.25, l_knee_p: 0.5, l_ankle_p: -0.25, r_hip_p: -0.25, "
                           "r_knee_p: 0.5, r_ankle_p: -0.25}");
}

// Both feet on the floor of flat_ground, where the humanoid_walk scenario starts.
const char* kFeet =
    "    - {s1: robot/l_sole, s2: env/floor, placement: [-1.5, 0.085, 0]}\n"
    "    - {s1: robot/r_sole, s2: env/floor, placement: [-1.5, -0.085, 0]}\n";

std::string write(const std::string& name, const std::string& text) {
  const std::string path = (test::temp_dir("limits") / (name + ".yaml")).string();
  std::ofstream(path) << text;
  return path;
}

std::string error_of(const std::string& path) {
  try {
    load_scenario(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Limits, AStanceWithoutContactsIsRejectedForAFloatingRobot) {
  const std::string path =
      write("no_contacts", entities("flat_ground") + "stances:\n  initial: []\n  goal:\n" + kFeet);
  EXPECT_EQ(
      error_of(path),
      path +
          ":15: stances.initial: expected at least one contact, found none: the floating entity "
          "\"robot\" cannot be in static equilibrium under gravity without one");
  const std::string goal =
      write("no_goal_contacts",
            entities("flat_ground") + "stances:\n  initial:\n" + kFeet + "  goal: []\n");
  EXPECT_THAT(error_of(goal),
              HasSubstr(":18: stances.goal: expected at least one contact, found none"));
  // Without gravity nothing needs support: the empty stance is allowed.
  const std::string weightless = write(
      "weightless", entities("flat_ground") +
                        "stances:\n  initial: []\n  goal: []\nphysics:\n  gravity: [0, 0, 0]\n");
  EXPECT_EQ(error_of(weightless), "");
}

TEST(Limits, AContactBetweenTwoSurfacesOfOneLinkIsRejected) {
  const std::string path =
      write("same_link", entities("desk_room") + "stances:\n  initial:\n" +
                             "    - {s1: robot/l_sole, s2: env/floor}\n"
                             "    - {s1: env/chair_seat, s2: env/chair_back}\n"
                             "  goal:\n    - {s1: robot/l_sole, s2: env/floor}\n");
  EXPECT_EQ(error_of(path),
            path + ":17: stances.initial[1]: s1 and s2 are on the same link \"chair\"");
}

TEST(Limits, ASurfaceUsedTwiceInOneStanceIsRejected) {
  // As the smaller surface of two contacts, and as the larger surface after being the smaller one.
  const std::string twice =
      write("twice_s1", entities("flat_ground") + "stances:\n  initial:\n" +
                            "    - {s1: robot/l_sole, s2: env/floor}\n"
                            "    - {s1: robot/l_sole, s2: env/floor}\n"
                            "  goal:\n    - {s1: robot/l_sole, s2: env/floor}\n");
  EXPECT_EQ(error_of(twice), twice +
                                 ":17: stances.initial[1].s1: surface \"robot/l_sole\" is already "
                                 "in a contact of this stance");
  const std::string as_s2 =
      write("twice_s2", entities("flat_ground") + "stances:\n  initial:\n" +
                            "    - {s1: robot/l_sole, s2: env/floor}\n"
                            "    - {s1: robot/r_palm, s2: robot/l_sole}\n"
                            "  goal:\n    - {s1: robot/l_sole, s2: env/floor}\n");
  EXPECT_EQ(error_of(as_s2), as_s2 +
                                 ":17: stances.initial[1].s2: surface \"robot/l_sole\" is already "
                                 "the smaller surface of a contact of this stance");
}

// A goal equal to the start, guided by one milestone (the start itself): the plan is the initial
// stance alone, and it certifies.
TEST(Limits, AGoalEqualToTheStartWithOneMilestoneIsAOneStepPlanThatCertifies) {
  const std::string path = write(
      "goal_is_start", entities("flat_ground") + "stances:\n  initial:\n" + kFeet + "  goal:\n" +
                           kFeet + "guide:\n  - robot: {base_position: [0, 0, 0.90]}\n");
  const Scenario scenario = load_scenario(path);
  EXPECT_EQ(scenario.milestones.size(), 1u);
  const std::string out = (test::temp_dir("limits") / "goal_is_start.json").string();
  const test::CliResult planned = test::run_cli({"plan", path, "--out", out, "--threads", "1"});
  ASSERT_EQ(planned.code, 0) << planned.err;
  EXPECT_THAT(planned.out, HasSubstr(": 1 steps, 0 nodes expanded"));
  EXPECT_EQ(read_plan(out).plan.steps.size(), 1u);
  const test::CliResult certified = test::run_cli({"certify", out});
  EXPECT_EQ(certified.code, 0) << certified.out << certified.err;
}

TEST(Limits, AMilestoneNamingNoEntityOrAnEmptyGuideIsNamed) {
  const std::string unknown =
      write("milestone_unknown", entities("flat_ground") + "stances:\n  initial:\n" + kFeet +
                                     "  goal:\n" + kFeet +
                                     "guide:\n  - robt: {base_position: [0, 0, 0.9]}\n");
  EXPECT_EQ(error_of(unknown), unknown + ":22: guide[0].robt: no entity \"robt\"");
  // An empty guide is no guide: the search ranks nodes by the stance difference alone.
  const std::string empty =
      write("guide_empty", entities("flat_ground") + "stances:\n  initial:\n" + kFeet +
                               "  goal:\n" + kFeet + "guide: []\n");
  EXPECT_EQ(error_of(empty), "");
  EXPECT_TRUE(load_scenario(empty).milestones.empty());
}

}  // namespace
}  // namespace stanceplan
