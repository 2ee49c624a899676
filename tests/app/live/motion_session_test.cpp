// The panel's motion worker (app/live/motion_session.h): the motions of a plan computed one step at
// a time on a thread, the same as the command line computes them, and a cancel that stops it.
#include <gtest/gtest.h>

#include <chrono>

#include "app/live/motion_session.h"
#include "planner/motion/plan_motion.h"
#include "tests/support/forward_step.h"

namespace stanceplan::app {
namespace {

using std::chrono::seconds;

TEST(MotionSession, ComputesTheSameMotionAsTheCommandLine) {
  test::ForwardStep fs = test::forward_step_plan();
  MotionSession session(fs.scenario.scene, fs.scenario.solver, MotionOptions{}, fs.plan);
  EXPECT_EQ(session.progress().steps_done, 0);
  session.start();
  ASSERT_TRUE(session.wait_until_finished(seconds(120)));
  const MotionProgress progress = session.progress();
  EXPECT_EQ(progress.steps_done, 2);
  EXPECT_EQ(progress.steps_failed, 0) << progress.first_failure;
  EXPECT_FALSE(progress.cancelled);
  const Plan moved = session.plan();
  ASSERT_TRUE(add_motion(fs.scenario.scene, fs.scenario.solver, MotionOptions{}, fs.plan).solved());
  for (size_t i = 1; i < 3; ++i) {
    ASSERT_TRUE(moved.steps[i].motion.has_value()) << "step " << i;
    const std::vector<MotionSample>& got = moved.steps[i].motion->samples;
    const std::vector<MotionSample>& want = fs.plan.steps[i].motion->samples;
    ASSERT_EQ(got.size(), want.size()) << "step " << i;
    ASSERT_FALSE(got.empty());
    EXPECT_TRUE(got.back().q.isApprox(want.back().q, 1e-12)) << "step " << i;
  }
}

TEST(MotionSession, ACancelBeforeTheFirstStepComputesNothing) {
  test::ForwardStep fs = test::forward_step_plan();
  MotionSession session(fs.scenario.scene, fs.scenario.solver, MotionOptions{}, fs.plan);
  session.cancel();
  session.start();
  ASSERT_TRUE(session.wait_until_finished(seconds(60)));
  EXPECT_TRUE(session.progress().cancelled);
  EXPECT_EQ(session.progress().steps_done, 0);
  EXPECT_FALSE(session.plan().steps[1].motion.has_value());
}

TEST(MotionSession, AStepWhoseMotionFailsIsKeptWithoutOne) {
  // Samples no joint may leave (a spacing nothing meets within the halvings) fail every step.
  test::ForwardStep fs = test::forward_step_plan();
  MotionOptions options;
  options.joint_spacing = 1e-9;
  options.max_halvings = 1;
  options.detour.max_projections = 0;  // no detour either (2 x 2500 projections: 24 s, 130 s TSan)
  MotionSession session(fs.scenario.scene, fs.scenario.solver, options, fs.plan);
  session.start();
  ASSERT_TRUE(session.wait_until_finished(seconds(120)));
  const MotionProgress progress = session.progress();
  EXPECT_EQ(progress.steps_done, 2);
  EXPECT_EQ(progress.steps_failed, 2);
  EXPECT_EQ(progress.first_failure.rfind("step 1: ", 0), 0u) << progress.first_failure;
  EXPECT_FALSE(session.plan().steps[1].motion.has_value());
  EXPECT_FALSE(session.plan().steps[2].motion.has_value());
}

}  // namespace
}  // namespace stanceplan::app
