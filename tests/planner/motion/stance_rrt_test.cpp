// The detour on the stance manifold (planner/motion/stance_rrt.h): a travel whose straight
// interpolation stops short (here: its projection budget cut to 10) is finished by the detour, the
// plan certifies sample by sample, and the same inputs give the same samples.
#include <gtest/gtest.h>

#include "planner/certify/certify.h"
#include "planner/motion/plan_motion.h"
#include "tests/support/forward_step.h"

namespace stanceplan {
namespace {

// Enough projections for the lift and the approach (3 cm at 1 cm a sample), not for the 20 cm
// travel between them.
MotionOptions short_budget() {
  MotionOptions o;
  o.max_solves = 10;
  return o;
}

TEST(StanceDetour, TravelCutShortIsFinishedByTheDetourAndCertifies) {
  test::ForwardStep fs = test::forward_step_plan();
  MotionOptions without = short_budget();
  without.detour.max_projections = 0;  // no detour: the straight travel alone fails
  Plan straight = fs.plan;
  const PlanMotionSummary failed =
      add_motion(fs.scenario.scene, fs.scenario.solver, without, straight);
  ASSERT_EQ(failed.failed_steps, 1) << failed.first_failure;
  EXPECT_NE(failed.first_failure.find("travel"), std::string::npos) << failed.first_failure;

  const PlanMotionSummary summary =
      add_motion(fs.scenario.scene, fs.scenario.solver, short_budget(), fs.plan);
  ASSERT_TRUE(summary.solved()) << summary.first_failure;
  EXPECT_GT(summary.steps[1].solves, failed.steps[1].solves);  // the detour's projections
  const CertifyReport report = certify(fs.scenario.scene, fs.scenario.solver.friction, fs.plan);
  for (const CheckResult& c : report.checks)
    EXPECT_TRUE(c.passed()) << c.name << " " << c.worst << " at step " << c.step << ": "
                            << c.detail;
  EXPECT_TRUE(report.passed());
}

TEST(StanceDetour, SameInputsGiveTheSameSamples) {
  test::ForwardStep fs = test::forward_step_plan();
  Plan first = fs.plan, second = fs.plan;
  ASSERT_TRUE(add_motion(fs.scenario.scene, fs.scenario.solver, short_budget(), first).solved());
  ASSERT_TRUE(add_motion(fs.scenario.scene, fs.scenario.solver, short_budget(), second).solved());
  const auto& a = first.steps[2].motion->samples;
  const auto& b = second.steps[2].motion->samples;
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a[k].q, b[k].q) << "sample " << k;
}

TEST(StanceDetour, BadOptionsAreRefusedByName) {
  MotionOptions o;
  o.detour.step = 1.5;
  EXPECT_EQ(check_motion_options(o), "detour.step: expected a number in (0, 1], found 1.5");
}

}  // namespace
}  // namespace stanceplan
