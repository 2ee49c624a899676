// Scenario files: what they load into, and every class of fault with its exact message
// ("FILE:LINE: FIELD: what was expected, what was found").
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "planner/io/scenario.h"
#include "planner/util/input_error.h"
#include "tests/support/paths.h"
#include "tests/support/scenario_text.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

// A valid scenario in a temporary folder, with `change` applied to its text.
class ScenarioFaults : public ::testing::Test {
 protected:
  std::string header() const { return test::humanoid_on("flat_ground", "{l_knee_p: 0.4}"); }
  std::string stances() const {
    return "stances:\n"                                  // 14
           "  initial:\n"                                // 15
           "    - {s1: robot/l_sole, s2: env/floor}\n"   // 16
           "    - {s1: robot/r_sole, s2: env/floor}\n"   // 17
           "  goal:\n"                                   // 18
           "    - {s1: robot/l_sole, s2: env/floor}\n";  // 19
  }
  void SetUp() override {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    path_ = (test::temp_dir("scenarios") / (name + ".yaml")).string();
  }
  std::string write(const std::string& text) {
    std::ofstream(path_) << text;
    return path_;
  }
  std::string error_of(const std::string& text) {
    write(text);
    try {
      load_scenario(path_);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  std::string path_;
};

TEST_F(ScenarioFaults, AValidScenarioLoads) {
  const Scenario s = load_scenario(
      write(header() + stances() +
            "guide:\n  - robot: {base_position: [0.3, 0, 0.9]}\n    tolerance: 0.05\n"));
  EXPECT_EQ(s.scene.system.num_entities(), 2);
  EXPECT_EQ(s.initial_stance.size(), 2u);
  EXPECT_EQ(s.goal_stance.size(), 1u);
  ASSERT_EQ(s.milestones.size(), 1u);
  EXPECT_NEAR(s.milestones[0][0], 0.3, 1e-12);
  EXPECT_NEAR(s.milestone_tolerances[0], 0.05, 1e-12);
  EXPECT_EQ(s.milestone_masks[0].sum(), 3.0);  // only the base position is stated
  const Model& m = *s.scene.system.entity(0).model;
  EXPECT_NEAR(s.initial_configuration[7 + m.find_dof("l_knee_p")], 0.4, 1e-12);
  EXPECT_NEAR(s.milestones[0][7 + m.find_dof("l_knee_p")], 0.4,
              1e-12);  // completed from the initial one
}

TEST_F(ScenarioFaults, AMilestoneStatesTheContactsOfferedWhileItIsTheTarget) {
  const Scenario s =
      load_scenario(write(header() + stances() +
                          "guide:\n"
                          "  - robot: {base_position: [0.3, 0, 0.9]}\n"
                          "    contacts: [[robot/*_sole, env/floor], [robot/l_hand, env/*]]\n"
                          "  - robot: {base_position: [0.6, 0, 0.9]}\n"));
  ASSERT_EQ(s.milestone_contact_pairs.size(), 2u);
  using Pairs = std::vector<std::pair<std::string, std::string>>;
  EXPECT_EQ(s.milestone_contact_pairs[0],
            (Pairs{{"robot/*_sole", "env/floor"}, {"robot/l_hand", "env/*"}}));
  EXPECT_TRUE(s.milestone_contact_pairs[1].empty());  // the search's contact_pairs apply
  EXPECT_EQ(
      error_of(header() + stances() +
               "guide:\n  - robot: {base_position: [0.3, 0, 0.9]}\n    contacts: [robot/l_sole]\n"),
      path_ + ":22: guide[0].contacts[0]: expected [s1 pattern, s2 pattern]");
  EXPECT_EQ(
      error_of(header() + stances() +
               "guide:\n  - robot: {base_position: [0.3, 0, 0.9]}\n    contacts: robot/l_sole\n"),
      path_ + ":22: guide[0].contacts: expected a list of [s1 pattern, s2 pattern]");
}

TEST_F(ScenarioFaults, AnUnknownSurfaceIsNamedWithLineAndField) {
  std::string text = header() + stances();
  text.replace(text.find("s1: robot/r_sole, s2: env/floor"), 31, "s1: robot/r_sole, s2: env/flor");
  EXPECT_EQ(
      error_of(text),
      path_ + ":17: stances.initial[1].s2: no surface \"env/flor\" (entity \"env\" has: floor)");
}

TEST_F(ScenarioFaults, AMisspeltFieldIsAnError) {
  EXPECT_EQ(error_of(header() + stances() + "colision:\n  margin: 0.01\n"),
            path_ +
                ":20: colision: unknown field (expected one of: format, name, description, "
                "entities, stances, "
                "guide, physics, weights, collision, search, solver)");
}

TEST_F(ScenarioFaults, AJointOutsideItsLimitsIsNamed) {
  std::string text = header() + stances();
  text.replace(text.find("{l_knee_p: 0.4}"), 15, "{l_knee_p: 3.0}");
  EXPECT_EQ(error_of(text),
            path_ +
                ":9: entities[0].configuration.joints.l_knee_p: 3.000000 is outside the joint's "
                "limits [0.000000, 2.500000]");
}

TEST_F(ScenarioFaults, AnUnknownJointIsNamed) {
  std::string text = header() + stances();
  text.replace(text.find("{l_knee_p: 0.4}"), 15, "{l_knee: 0.4}");
  EXPECT_EQ(error_of(text), path_ +
                                ":9: entities[0].configuration.joints.l_knee: model \"humanoid\" "
                                "has no joint \"l_knee\"");
}

TEST_F(ScenarioFaults, WrongKindsAndNumbersAreNamed) {
  std::string text = header() + stances();
  text.replace(text.find("kind: floating"), 14, "kind: flying");
  EXPECT_EQ(error_of(text), path_ +
                                ":4: entities[0].kind: expected floating, fixed, object or "
                                "environment, found \"flying\"");
  EXPECT_EQ(error_of(header() + stances() + "physics:\n  friction: lots\n"),
            path_ + ":21: physics.friction: expected a number, found \"lots\"");
  EXPECT_EQ(error_of(header() + stances() + "physics:\n  friction: -1\n"),
            path_ + ":21: physics.friction: expected a number > 0, found -1");
}

TEST_F(ScenarioFaults, MinContactsIsAWholeNumberOfAtLeastOne) {
  write(header() + stances() + "search:\n  min_contacts: 3\n");
  EXPECT_EQ(load_scenario(path_).search.min_contacts, 3);
  EXPECT_EQ(SearchOptions{}.min_contacts, 1);
  EXPECT_EQ(error_of(header() + stances() + "search:\n  min_contacts: 0\n"),
            path_ + ":21: search.min_contacts: expected a whole number >= 1, found 0");
  EXPECT_EQ(error_of(header() + stances() + "search:\n  min_contacts: 2.5\n"),
            path_ + ":21: search.min_contacts: expected a whole number >= 1, found 2.5");
}

// The batch margin (search.batch_margin, m): a number, negative turns the batch of one off.
TEST_F(ScenarioFaults, TheBatchMarginIsANumber) {
  write(header() + stances() + "search:\n  batch_margin: -1\n");
  EXPECT_EQ(load_scenario(path_).search.batch_margin, -1.0);
  EXPECT_EQ(SearchOptions{}.batch_margin, 0.03);
  EXPECT_EQ(error_of(header() + stances() + "search:\n  batch_margin: wide\n"),
            path_ + ":21: search.batch_margin: expected a number, found \"wide\"");
}

TEST_F(ScenarioFaults, SkippingUnreachedMilestonesIsOnUnlessTheFileSaysFalse) {
  EXPECT_TRUE(SearchOptions{}.skip_unreached_milestones);
  write(header() + stances() + "search:\n  skip_unreached_milestones: false\n");
  EXPECT_FALSE(load_scenario(path_).search.skip_unreached_milestones);
  EXPECT_THAT(error_of(header() + stances() + "search:\n  skip_unreached_milestones: maybe\n"),
              ::testing::StartsWith(path_ + ":21: search.skip_unreached_milestones: expected true "
                                            "or false"));
}

TEST_F(ScenarioFaults, AdvancingPastMilestonesIsOnUnlessTheFileSaysFalse) {
  EXPECT_TRUE(SearchOptions{}.advance_past_milestones);
  write(header() + stances() + "search:\n  advance_past_milestones: false\n");
  EXPECT_FALSE(load_scenario(path_).search.advance_past_milestones);
  EXPECT_THAT(error_of(header() + stances() + "search:\n  advance_past_milestones: 2\n"),
              ::testing::StartsWith(path_ + ":21: search.advance_past_milestones: expected true "
                                            "or false"));
}

// The computed guide's budget is a whole number of validity checks; the old wall-clock field is
// refused with the field to write instead (no number of seconds means the same on every machine).
TEST_F(ScenarioFaults, TheGuideBudgetIsCountedInChecksNotSeconds) {
  write(header() + stances() + "search:\n  guide_max_checks: 5000\n");
  EXPECT_EQ(load_scenario(path_).guide.max_checks, 5000);
  EXPECT_EQ(error_of(header() + stances() + "search:\n  guide_max_checks: 0\n"),
            path_ + ":21: search.guide_max_checks: expected a whole number >= 1, found 0");
  EXPECT_EQ(error_of(header() + stances() + "search:\n  guide_time_limit: 5\n"),
            path_ +
                ":21: search.guide_time_limit: replaced by search.guide_max_checks, the "
                "guide's budget in validity checks (default " +
                std::to_string(GuideOptions{}.max_checks) +
                "): seconds gave different guides on different machines");
}

TEST_F(ScenarioFaults, MissingSectionsAndFiles) {
  EXPECT_EQ(error_of(header()), path_ + ":1: stances: missing");
  std::string text = header() + stances();
  text.replace(text.find("humanoid.urdf"), 13, "humanoid_missing.urdf");
  EXPECT_THAT(error_of(text), HasSubstr("humanoid_missing.urdf: no such file"));
  EXPECT_EQ(error_of("format: stanceplan/plan@1\n"),
            path_ + ":1: format: expected \"stanceplan/scenario@1\", found \"stanceplan/plan@1\"");
  try {
    load_scenario("/nonexistent/s.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/s.yaml: no such file");
  }
}

// The fuzzer's find: a folder where a file was expected used to abort inside the YAML parser.
TEST_F(ScenarioFaults, AFolderWhereAFileWasExpectedIsNamed) {
  std::string text = header() + stances();
  const std::string surfaces = "/robots/humanoid/humanoid.surfaces.yaml";
  const std::size_t at = text.find(surfaces);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, surfaces.size(), "/robots/humanoid");
  EXPECT_THAT(error_of(text), HasSubstr("/robots/humanoid: not a regular file (a folder?)"));
  const std::string folder = test::temp_dir("scenario_folder").string();
  try {
    load_scenario(folder);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), folder + ": not a regular file (a folder?)");
  }
}

TEST_F(ScenarioFaults, ASurfaceTwiceInAStanceIsRejected) {
  std::string text = header() + stances();
  text.replace(text.find("s1: robot/r_sole, s2: env/floor"), 31, "s1: robot/l_sole, s2: env/floor");
  EXPECT_EQ(error_of(text), path_ +
                                ":17: stances.initial[1].s1: surface \"robot/l_sole\" is already "
                                "in a contact of this stance");
}

// A point surface (a sphere at a point of a link) touches a polygon: it is the s1 of a contact and
// never its s2; the contact is named, and so is the fix.
TEST_F(ScenarioFaults, APointSurfaceIsOnlyEverS1) {
  const std::string humanoid = test::source_path("assets/robots/humanoid/humanoid.surfaces.yaml");
  const std::string with_tip = (test::temp_dir("scenarios") / "humanoid_with_tip.yaml").string();
  {
    std::ifstream in(humanoid);
    std::ofstream out(with_tip);
    out << in.rdbuf() << "  - {name: l_tip, link: l_hand, point: [0, 0, -0.15], radius: 0.02}\n"
        << "  - {name: r_tip, link: r_hand, point: [0, 0, -0.15], radius: 0.02}\n";
  }
  std::string text = header() + stances();
  text.replace(text.find(humanoid), humanoid.size(), with_tip);
  const size_t goal = text.find("  goal:\n");
  EXPECT_EQ(load_scenario(write(text.substr(0, goal) + "    - {s1: robot/l_tip, s2: env/floor}\n" +
                                text.substr(goal)))
                .initial_stance.size(),
            3u);
  EXPECT_EQ(error_of(text.substr(0, goal) + "    - {s1: env/floor, s2: robot/l_tip}\n" +
                     text.substr(goal)),
            path_ +
                ":18: stances.initial[2].s2: contact env/floor - robot/l_tip: s2 "
                "\"robot/l_tip\" is a point surface, which can only be the s1 of a contact (s2 "
                "must be a polygon; swap s1 and s2)");
  EXPECT_EQ(error_of(text.substr(0, goal) + "    - {s1: robot/r_tip, s2: robot/l_tip}\n" +
                     text.substr(goal)),
            path_ +
                ":18: stances.initial[2].s2: contact robot/r_tip - robot/l_tip: s2 "
                "\"robot/l_tip\" is a point surface, which can only be the s1 of a contact (s2 "
                "must be a polygon: two points cannot touch)");
}

}  // namespace
}  // namespace stanceplan
