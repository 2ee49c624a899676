// SearchDriver: the panel's controls over a real search (the walk), one frame at a time. Each
// "frame" hands the driver the events that arrived since the previous one, as the panel does.
#include "app/gui/search_driver.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "app/gui/session_mirror.h"
#include "app/live/plan_session.h"
#include "tests/support/paths.h"

namespace stanceplan::gui {
namespace {

using namespace std::chrono_literals;

// Long enough for the search to publish an event if the gate let it through.
constexpr auto kQuiet = 300ms;

class DriverTest : public ::testing::Test {
 protected:
  DriverTest() : scenario_(load_scenario(test::source_path("scenarios/humanoid_walk.yaml"))) {
    SearchOptions options = scenario_.search;
    options.threads = 1;
    session_ = std::make_unique<app::PlanSession>(scenario_, options);
  }

  // One panel frame: copy the new events and hand their kinds to the driver; then, unless the
  // driver paused, wait (up to 60 s) for the event its step let through.
  void frame(SearchDriver& driver) {
    const size_t before = mirror_.events().size();
    mirror_.sync(*session_);
    std::vector<SearchEventKind> arrived;
    for (size_t i = before; i < mirror_.events().size(); ++i)
      arrived.push_back(mirror_.events()[i].kind);
    driver.update(arrived, 1.0 / 30.0);
    if (driver.mode() != RunMode::Paused) session_->wait_for_event(mirror_.events().size(), 60s);
  }

  Scenario scenario_;
  std::unique_ptr<app::PlanSession> session_;
  SessionMirror mirror_;
};

TEST_F(DriverTest, StartsPausedAndStepsExactlyOneEvent) {
  SearchDriver driver(session_->gate(), true);
  session_->start();
  EXPECT_FALSE(session_->wait_for_event(0, kQuiet));
  driver.step_event();
  driver.update({}, 0.0);
  ASSERT_TRUE(session_->wait_for_event(0, 60s));
  EXPECT_FALSE(session_->wait_for_event(1, kQuiet)) << "one step, one event";
  EXPECT_EQ(driver.mode(), RunMode::Paused);
}

TEST_F(DriverTest, StepExpansionStopsRightAfterTheNextExpansion) {
  SearchDriver driver(session_->gate(), true);
  session_->start();
  for (int round = 0; round < 2; ++round) {
    driver.step_expansion();
    for (int guard = 0; driver.mode() != RunMode::Paused && guard < 10000; ++guard) frame(driver);
    ASSERT_EQ(driver.mode(), RunMode::Paused);
    mirror_.sync(*session_);
    ASSERT_FALSE(mirror_.events().empty());
    EXPECT_EQ(mirror_.events().back().kind, SearchEventKind::Expansion) << "round " << round;
    EXPECT_FALSE(session_->wait_for_event(mirror_.events().size(), kQuiet)) << "no overshoot";
  }
  // Two expansions: the root's, then the best child's.
  EXPECT_EQ(mirror_.last_of(SearchEventKind::Expansion, mirror_.events().size()),
            static_cast<long>(mirror_.events().size()) - 1);
}

TEST_F(DriverTest, NextMilestoneStopsOnTheMilestoneEvent) {
  SearchDriver driver(session_->gate(), true);
  session_->start();
  driver.next_milestone();
  for (int guard = 0; driver.mode() != RunMode::Paused && guard < 100000; ++guard) frame(driver);
  ASSERT_EQ(driver.mode(), RunMode::Paused);
  const SearchEvent& last = mirror_.events().back();
  EXPECT_EQ(last.kind, SearchEventKind::Milestone);
  EXPECT_EQ(last.milestone, 1);
  EXPECT_FALSE(session_->wait_for_event(mirror_.events().size(), kQuiet)) << "no overshoot";
  // Run to the end from there.
  driver.run();
  driver.update({}, 0.0);
  ASSERT_TRUE(session_->wait_until_finished(120s));
  mirror_.sync(*session_);
  ASSERT_TRUE(mirror_.finished());
  EXPECT_EQ(mirror_.result()->status, PlanStatus::Found);
  EXPECT_EQ(mirror_.tree().goal(), mirror_.result()->closest_node);
  EXPECT_EQ(mirror_.tree().plan_path().size(), mirror_.result()->plan.steps.size());
}

// The speed limit grants events through the gate's budget: 10 events/s for 0.25 s = 2 events
// (capped at a fifth of a second's worth), and no more until they have been seen.
TEST(SearchDriverGate, TheSpeedLimitGrantsEventsByElapsedTime) {
  StepGate gate;
  SearchDriver driver(gate, false);
  driver.set_speed_limit(10.0);
  driver.update({}, 0.25);
  EXPECT_FALSE(gate.paused());
  EXPECT_TRUE(gate.pass());
  EXPECT_TRUE(gate.pass());
  EXPECT_TRUE(gate.paused()) << "two events granted, both used";
  driver.update({}, 0.05);  // 0.5 event earned: not yet one
  EXPECT_TRUE(gate.paused());
  driver.update({SearchEventKind::Candidate, SearchEventKind::Candidate}, 0.05);
  EXPECT_FALSE(gate.paused()) << "one more event earned";
  driver.set_speed_limit(0.0);
  driver.update({}, 0.0);
  EXPECT_FALSE(gate.paused());
  driver.pause();
  driver.update({}, 0.0);
  EXPECT_TRUE(gate.paused());
}

}  // namespace
}  // namespace stanceplan::gui
