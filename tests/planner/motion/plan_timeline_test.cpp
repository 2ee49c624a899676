// Positions on a plan's timeline (planner/plan/plan_timeline.h): the GIF and the panel play the
// motion into each step over one unit of position, its samples evenly spaced.
#include <gtest/gtest.h>

#include <limits>

#include "planner/plan/plan_timeline.h"

namespace stanceplan {
namespace {

// Three steps; the motion into step 1 has `samples` samples, step 2 has none.
Plan plan_with_samples(int samples) {
  Plan plan;
  plan.steps.resize(3);
  plan.steps[1].motion = StepMotion{};
  plan.steps[1].motion->samples.resize(static_cast<size_t>(samples));
  return plan;
}

TEST(PlanTimeline, APlanHasMotionWhenAStepHoldsSamples) {
  EXPECT_TRUE(has_motion(plan_with_samples(3)));
  EXPECT_FALSE(has_motion(plan_with_samples(0)));  // a motion without samples (a failed one)
  Plan steps_only;
  steps_only.steps.resize(3);
  EXPECT_FALSE(has_motion(steps_only));
}

TEST(PlanTimeline, StepsSitAtWholePositions) {
  const Plan plan = plan_with_samples(3);
  EXPECT_EQ(timeline_point(plan, 0.0), (TimelinePoint{0, -1}));
  EXPECT_EQ(timeline_point(plan, 1.0), (TimelinePoint{1, -1}));
  EXPECT_EQ(timeline_point(plan, 2.0), (TimelinePoint{2, -1}));
}

TEST(PlanTimeline, SamplesAreEvenlySpacedBetweenTheirSteps) {
  // [step 0, s0, s1, s2, step 1] at 0, 1/4, 2/4, 3/4, 1: the nearest one is shown.
  const Plan plan = plan_with_samples(3);
  EXPECT_EQ(timeline_point(plan, 0.1), (TimelinePoint{0, -1}));
  EXPECT_EQ(timeline_point(plan, 0.25), (TimelinePoint{1, 0}));
  EXPECT_EQ(timeline_point(plan, 0.45), (TimelinePoint{1, 1}));
  EXPECT_EQ(timeline_point(plan, 0.76), (TimelinePoint{1, 2}));
  EXPECT_EQ(timeline_point(plan, 0.9), (TimelinePoint{1, -1}));
}

TEST(PlanTimeline, AStepWithoutMotionIsHeldUntilTheNextOne) {
  const Plan plan = plan_with_samples(3);
  EXPECT_EQ(timeline_point(plan, 1.2), (TimelinePoint{1, -1}));
  EXPECT_EQ(timeline_point(plan, 1.99), (TimelinePoint{1, -1}));
}

TEST(PlanTimeline, PositionsOffTheTimelineAreClamped) {
  const Plan plan = plan_with_samples(3);
  EXPECT_EQ(timeline_point(plan, -3.0), (TimelinePoint{0, -1}));
  EXPECT_EQ(timeline_point(plan, 7.5), (TimelinePoint{2, -1}));
  EXPECT_EQ(timeline_point(plan, std::numeric_limits<double>::quiet_NaN()), (TimelinePoint{0, -1}));
  EXPECT_EQ(timeline_point(Plan{}, 0.5), (TimelinePoint{0, -1}));
}

}  // namespace
}  // namespace stanceplan
