// PlanSession: the search on a worker thread, its events stored in order for any number of
// readers, the step gate driven the way the panel drives it, cancellation.
#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <thread>

#include "app/live/plan_session.h"
#include "tests/support/paths.h"
#include "tests/support/planned_scenario.h"

namespace stanceplan {
namespace {

using namespace std::chrono_literals;
using app::PlanSession;

// Long enough for the search to publish an event if the gate let it: a walk candidate solves in
// tens of milliseconds.
constexpr auto kQuiet = 300ms;
constexpr auto kPatience = 60s;

TEST(PlanSession, RunsTheWalkOnItsThreadAndKeepsEveryEventInOrder) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  PlanSession session(scenario, test::one_process(scenario));
  EXPECT_FALSE(session.finished());
  session.start();
  // A reader with its own cursor, as the snapshot writer and the panel read.
  size_t seen = 0;
  while (session.wait_for_event(seen, kPatience)) {
    EXPECT_EQ(session.event(seen).number, static_cast<int>(seen));
    ++seen;
  }
  ASSERT_TRUE(session.wait_until_finished(kPatience));
  ASSERT_TRUE(session.result().has_value());
  EXPECT_EQ(session.result()->status, PlanStatus::Found);
  EXPECT_EQ(seen, session.event_count());
  EXPECT_EQ(session.event(seen - 1).kind, SearchEventKind::PlanFound);
  EXPECT_FALSE(session.error());
  for (size_t i = 1; i < seen; ++i) EXPECT_GE(session.event_time_s(i), session.event_time_s(i - 1));
}

// With motion, the search thread checks the plan's transitions (the motion planner's Ipopt in
// this process, beside the forked workers) while this thread reads events: the plan carries every
// step's motion, and the checks are reported once the session finished.
TEST(PlanSession, WithMotionThePlanFoundCarriesEveryStepsMotion) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  PlanSession session(scenario, test::one_process(scenario), MotionOptions{});
  EXPECT_THROW(session.motion_checks(), std::logic_error);  // not before the search finished
  session.start();
  for (size_t seen = 0; session.wait_for_event(seen, kPatience);) ++seen;
  ASSERT_TRUE(session.wait_until_finished(kPatience));
  ASSERT_TRUE(session.result().has_value());
  const SearchResult result = *session.result();  // a copy: result() returns one
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  for (size_t i = 1; i < result.plan.steps.size(); ++i) {
    ASSERT_TRUE(result.plan.steps[i].motion.has_value()) << "step " << i;
    EXPECT_FALSE(result.plan.steps[i].motion->samples.empty()) << "step " << i;
  }
  EXPECT_EQ(session.motion_checks().size(), result.plan.steps.size() - 1);
  EXPECT_EQ(result.transitions_checked, int(result.plan.steps.size()) - 1);
}

// The panel's interface: while paused, no event happens; step(1) lets exactly one through.
TEST(PlanSession, TheStepGateDrivesTheSearchOneEventAtATime) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  PlanSession session(scenario, test::one_process(scenario));
  session.gate().pause();
  session.start();
  EXPECT_FALSE(session.wait_for_event(0, kQuiet)) << "paused before the first event";
  EXPECT_EQ(session.event_count(), 0u);
  EXPECT_TRUE(session.gate().paused());
  for (size_t i = 0; i < 6; ++i) {
    session.gate().step(1);
    ASSERT_TRUE(session.wait_for_event(i, kPatience)) << "step " << i;
    EXPECT_FALSE(session.wait_for_event(i + 1, kQuiet)) << "one event per step, at step " << i;
    EXPECT_EQ(session.event_count(), i + 1);
    EXPECT_EQ(session.event(i).number, static_cast<int>(i));
    EXPECT_TRUE(session.gate().paused());
    EXPECT_FALSE(session.finished());
  }
  session.gate().step(3);
  ASSERT_TRUE(session.wait_for_event(8, kPatience));
  EXPECT_FALSE(session.wait_for_event(9, kQuiet));
  EXPECT_EQ(session.event_count(), 9u);
  session.gate().resume();
  ASSERT_TRUE(session.wait_until_finished(kPatience));
  EXPECT_EQ(session.result()->status, PlanStatus::Found);
  EXPECT_EQ(session.event(session.event_count() - 1).kind, SearchEventKind::PlanFound);
}

TEST(PlanSession, CancelReleasesAPausedSearch) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  PlanSession session(scenario, test::one_process(scenario));
  session.gate().pause();
  session.start();
  session.gate().step(2);
  ASSERT_TRUE(session.wait_for_event(1, kPatience));
  session.cancel();
  ASSERT_TRUE(session.wait_until_finished(kPatience));
  ASSERT_TRUE(session.result().has_value());
  EXPECT_EQ(session.result()->status, PlanStatus::Cancelled);
  // The failure event is always delivered, even when cancelled, and is the last one.
  EXPECT_EQ(session.event(session.event_count() - 1).kind, SearchEventKind::Failure);
}

TEST(PlanSession, DestroyingARunningSessionCancelsAndJoins) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  SearchOptions options = scenario.search;
  options.threads = 2;  // with solver worker processes, forked from the session's thread
  {
    PlanSession session(scenario, options);
    session.start();
    ASSERT_TRUE(session.wait_for_event(2, kPatience));
  }  // the destructor cancels and joins; the test ends instead of hanging
  SUCCEED();
}

// The panel's Run again: after a cancel, restart() runs a new search from the start on the same
// solver processes and gate, whose events are numbered from 0 again, to the plan.
TEST(PlanSession, RestartAfterACancelRunsANewSearchToThePlan) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  PlanSession session(scenario, test::one_process(scenario));
  session.start();
  ASSERT_TRUE(session.wait_for_event(3, kPatience));
  session.cancel();
  ASSERT_TRUE(session.wait_until_finished(kPatience));
  ASSERT_TRUE(session.result().has_value());
  EXPECT_EQ(session.result()->status, PlanStatus::Cancelled);
  session.restart();
  EXPECT_FALSE(session.finished());
  ASSERT_TRUE(session.wait_until_finished(kPatience));
  ASSERT_TRUE(session.result().has_value());
  EXPECT_EQ(session.result()->status, PlanStatus::Found) << session.result()->message;
  ASSERT_GT(session.event_count(), 4u);
  EXPECT_EQ(session.event(0).number, 0);
  EXPECT_TRUE(session.event(0).accepted);
  EXPECT_EQ(session.event(session.event_count() - 1).kind, SearchEventKind::PlanFound);
}

// A paused gate stays paused across a restart: the new search waits for the panel.
TEST(PlanSession, RestartKeepsAPausedGatePaused) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  PlanSession session(scenario, test::one_process(scenario));
  session.gate().pause();
  session.gate().step(2);
  session.start();
  ASSERT_TRUE(session.wait_for_event(1, kPatience));
  session.cancel();
  ASSERT_TRUE(session.wait_until_finished(kPatience));
  session.gate().pause();
  session.restart();
  std::this_thread::sleep_for(kQuiet);
  EXPECT_EQ(session.event_count(), 0u) << "the restarted search ran past a paused gate";
  session.gate().step(1);
  ASSERT_TRUE(session.wait_for_event(0, kPatience));
  std::this_thread::sleep_for(kQuiet);
  EXPECT_EQ(session.event_count(), 1u);
}

}  // namespace
}  // namespace stanceplan
