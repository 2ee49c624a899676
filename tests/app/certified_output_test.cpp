// Plans leave the program certified (app/plan_output.h): a plan corrupted in memory (a link moved
// into another) is not written; with --partial only its certified prefix is.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/cli.h"
#include "app/plan_output.h"
#include "planner/io/scenario.h"
#include "planner/search/stance_search.h"
#include "tests/support/cli.h"
#include "tests/support/paths.h"
#include "tests/support/planned_scenario.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

class CertifiedOutput : public test::PlannedWalk {
 protected:
  // The walk's plan with step `step`'s left arm swung into the waist (l_shoulder_r at its lower
  // limit, -0.5 rad: the elbow link 9 cm inside the waist); every other step as planned.
  static Plan corrupted(int step) {
    Plan plan = result_->plan;
    const Entity& robot = scenario_->scene.system.entity(0);
    const int k = robot.model->find_dof("l_shoulder_r");
    plan.steps[size_t(step)].q[scenario_->scene.system.offset(0) + robot.first_dof() + k] = -0.5;
    return plan;
  }
  static std::string path(const std::string& name) {
    return (test::temp_dir("certified_output") / name).string();
  }
};

TEST_F(CertifiedOutput, TheWalkPlanIsCertifiedAndWritten) {
  ASSERT_EQ(result_->status, PlanStatus::Found) << result_->message;
  std::ostringstream err;
  EXPECT_EQ(app::write_certified_plan(result_->plan, *scenario_, path("walk.json"), false, err),
            app::kExitSuccess);
  EXPECT_EQ(err.str(), "");
  EXPECT_TRUE(std::filesystem::exists(path("walk.json")));
}

TEST_F(CertifiedOutput, APlanWithALinkMovedIntoAnotherIsNotWritten) {
  ASSERT_EQ(result_->status, PlanStatus::Found) << result_->message;
  ASSERT_GT(result_->plan.steps.size(), 6u);
  std::ostringstream err;
  EXPECT_EQ(app::write_certified_plan(corrupted(5), *scenario_, path("bad.json"), false, err),
            app::kExitFailed);
  EXPECT_FALSE(std::filesystem::exists(path("bad.json")));
  EXPECT_THAT(err.str(), HasSubstr("stanceplan: certification failed: interpenetration at step 5: "
                                   "robot/waist and robot/l_elbow_p_link ("));
  EXPECT_THAT(err.str(), HasSubstr("the plan fails certification from step 5; " + path("bad.json") +
                                   " not written"));
}

TEST_F(CertifiedOutput, PartialWritesOnlyTheCertifiedPrefix) {
  ASSERT_EQ(result_->status, PlanStatus::Found) << result_->message;
  std::ostringstream err;
  EXPECT_EQ(app::write_certified_plan(corrupted(5), *scenario_, path("prefix.json"), true, err),
            app::kExitFailed);
  EXPECT_THAT(err.str(), HasSubstr("wrote a PARTIAL plan to " + path("prefix.json") +
                                   ": the 5 certified steps before step 5"));
  std::ifstream in(path("prefix.json"));
  const auto plan = nlohmann::json::parse(in);
  EXPECT_EQ(plan["steps"].size(), 5u);
  EXPECT_EQ(plan["partial"]["reaches_goal"], false);
  EXPECT_THAT(plan["partial"]["reason"].get<std::string>(),
              HasSubstr("certification failed from step 5 (equilibrium moment at step 5: robot ("));
  // The independent reader agrees: the prefix passes `stanceplan certify`.
  const test::CliResult r = test::run_cli({"certify", path("prefix.json")});
  EXPECT_EQ(r.code, 0) << r.out << r.err;
}

TEST_F(CertifiedOutput, AFirstStepThatFailsLeavesNothingToWrite) {
  ASSERT_EQ(result_->status, PlanStatus::Found) << result_->message;
  std::ostringstream err;
  EXPECT_EQ(app::write_certified_plan(corrupted(0), *scenario_, path("none.json"), true, err),
            app::kExitFailed);
  EXPECT_FALSE(std::filesystem::exists(path("none.json")));
  EXPECT_THAT(err.str(), HasSubstr("from step 0;"));
}

}  // namespace
}  // namespace stanceplan
