// The panel's script (panel_script.h) and its runner (script_runner.h): what a script file may
// say, the exact messages for what it may not, and when each action counts as done.
#include "app/gui/panel_script.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "app/gui/script_runner.h"
#include "planner/util/input_error.h"

namespace stanceplan::gui {
namespace {

using ::testing::HasSubstr;

std::string parse_error(const std::string& text) {
  try {
    parse_panel_script(text, "s.txt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(PanelScript, EveryActionOfTheGrammarParses) {
  const std::vector<ScriptAction> a = parse_panel_script(
      "# a comment\n"
      "run\npause\n\nstep event\nstep expansion\nnext milestone\n"
      "speed 5   # events per second\nspeed 0\nwait 0.5\n"
      "wait-for plan\nwait-for failure\nwait-for end\nwait-for event 12\n"
      "select node 3\nselect event 0\ntimeline 4\norbit -120 40.5\nzoom -2\nreset view\n"
      "tab plots\ntab inspector\nscreenshot out/a.png\nexport view\nexport strip\ncancel\n"
      "rerun\nprint\nwait-for motion\ntimeline 2.25\nquit\n",
      "s.txt");
  ASSERT_EQ(a.size(), 29u);
  EXPECT_EQ(a[0].verb, ScriptVerb::Run);
  EXPECT_EQ(a[0].line, 2);
  EXPECT_EQ(a[2].verb, ScriptVerb::StepEvent);
  EXPECT_EQ(a[2].line, 5);
  EXPECT_EQ(a[5].verb, ScriptVerb::Speed);
  EXPECT_EQ(a[5].a, 5.0);
  EXPECT_EQ(a[5].text, "speed 5");
  EXPECT_EQ(a[7].verb, ScriptVerb::Wait);
  EXPECT_EQ(a[7].a, 0.5);
  EXPECT_EQ(a[11].verb, ScriptVerb::WaitForEvent);
  EXPECT_EQ(a[11].a, 12.0);
  EXPECT_EQ(a[15].verb, ScriptVerb::Orbit);
  EXPECT_EQ(a[15].a, -120.0);
  EXPECT_EQ(a[15].b, 40.5);
  EXPECT_EQ(a[16].a, -2.0);
  EXPECT_EQ(a[20].verb, ScriptVerb::Screenshot);
  EXPECT_EQ(a[20].path, "out/a.png");
  EXPECT_EQ(a[25].verb, ScriptVerb::Print);
  EXPECT_EQ(a[26].verb, ScriptVerb::WaitForMotion);
  EXPECT_EQ(a[27].verb, ScriptVerb::Timeline);
  EXPECT_EQ(a[27].a, 2.25);  // a quarter of the way through the motion into step 3
  EXPECT_EQ(a.back().verb, ScriptVerb::Quit);
}

TEST(PanelScript, ABadLineIsNamedWithWhatWasExpectedAndFound) {
  EXPECT_EQ(parse_error("run\n\nspeed fast\n"),
            "s.txt:3: \"speed\" takes a number >= 0, found \"fast\"");
  EXPECT_EQ(parse_error("jump\n"),
            "s.txt:1: expected an action (run, pause, step event, wait SECONDS, ...: "
            "docs/README.md), found \"jump\"");
  EXPECT_EQ(parse_error("step\n"),
            "s.txt:1: expected an action (run, pause, step event, wait SECONDS, ...: "
            "docs/README.md), found \"step\"");
  EXPECT_EQ(parse_error("run now\n"), "s.txt:1: \"run\" takes nothing after it, found \"now\"");
  EXPECT_EQ(parse_error("wait 0\n"),
            "s.txt:1: \"wait\" takes a number of seconds > 0, found \"0\"");
  EXPECT_EQ(parse_error("wait-for event 0\n"),
            "s.txt:1: \"wait-for event\" takes a count (an integer >= 1), found \"0\"");
  EXPECT_EQ(parse_error("select node 2.5\n"),
            "s.txt:1: \"select node\" takes an index (an integer >= 0), found \"2.5\"");
  EXPECT_EQ(parse_error("timeline -1\n"),
            "s.txt:1: \"timeline\" takes a number >= 0, found \"-1\"");
  EXPECT_EQ(parse_error("orbit 10\n"),
            "s.txt:1: \"orbit\" takes two numbers of pixels, DX DY, found \"10\"");
  EXPECT_EQ(parse_error("screenshot shot.jpg\n"),
            "s.txt:1: \"screenshot\" takes a file name ending in .png, found \"shot.jpg\"");
  EXPECT_EQ(parse_error("wait-for\n"),
            "s.txt:1: expected an action (run, pause, step event, wait SECONDS, ...: "
            "docs/README.md), found \"wait-for\"");
  EXPECT_EQ(parse_error("# nothing\n\n"),
            "s.txt: expected at least one action, found none (2 lines of blanks and comments)");
}

TEST(PanelScript, AMissingFileIsNamed) {
  try {
    read_panel_script("/nonexistent/script.txt");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "/nonexistent/script.txt: cannot read the panel script (no such file, or no "
                 "access)");
  }
}

ScriptProgress at(double t, size_t events, bool finished = false, bool found = false) {
  ScriptProgress p;
  p.now_s = t;
  p.events = events;
  p.finished = finished;
  p.found = found;
  p.status = finished ? (found ? "plan found" : "no plan (cancelled)") : "paused";
  return p;
}

TEST(ScriptRunner, AStepIsDoneWhenItsEventArrivedAndAWaitWhenItsTimeHasPassed) {
  ScriptRunner runner(parse_panel_script("step event\nwait 2\nrun\n", "s.txt"));
  const ScriptAction* step = runner.start(at(0.0, 4));
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->verb, ScriptVerb::StepEvent);
  EXPECT_EQ(runner.start(at(0.1, 4)), nullptr) << "one action at a time";
  EXPECT_EQ(runner.finish(at(0.1, 4)), nullptr) << "its event has not arrived";
  const ScriptAction* done = runner.finish(at(0.2, 5));
  ASSERT_EQ(done, step);
  EXPECT_EQ(script_report(*done, at(0.2, 5)), "line 1 \"step event\": 5 events, paused");
  ASSERT_NE(runner.start(at(1.0, 5)), nullptr);
  EXPECT_EQ(runner.finish(at(2.9, 5)), nullptr);
  EXPECT_NE(runner.finish(at(3.0, 5)), nullptr);
  EXPECT_EQ(runner.start(at(3.0, 5))->verb, ScriptVerb::Run);
  EXPECT_FALSE(runner.done());
  EXPECT_NE(runner.finish(at(3.0, 5)), nullptr);
  EXPECT_TRUE(runner.done());
}

TEST(ScriptRunner, WaitingForAPlanFailsWhenTheSearchEndsWithoutOne) {
  ScriptRunner runner(parse_panel_script("\nwait-for plan\n", "s.txt"));
  runner.start(at(0.0, 0));
  EXPECT_EQ(runner.finish(at(1.0, 40)), nullptr);
  try {
    runner.finish(at(2.0, 41, true, false));
    FAIL() << "no failure";
  } catch (const ScriptFailure& f) {
    EXPECT_STREQ(f.what(),
                 "line 2 \"wait-for plan\": the search ended without a plan: no plan (cancelled)");
  }
}

TEST(ScriptRunner, WaitingForAnEventCountsEventsAndFailsWhenTheSearchEndsShort) {
  ScriptRunner runner(parse_panel_script("wait-for event 10\nwait-for event 50\n", "s.txt"));
  runner.start(at(0.0, 0));
  EXPECT_EQ(runner.finish(at(0.0, 9)), nullptr);
  EXPECT_NE(runner.finish(at(0.0, 10)), nullptr);
  runner.start(at(0.0, 10));
  EXPECT_THROW(runner.finish(at(0.0, 30, true, true)), ScriptFailure);
}

TEST(ScriptRunner, WaitingForTheMotionEndsWhenEveryStepWasTriedAndFailsWithoutOne) {
  ScriptRunner runner(parse_panel_script("wait-for motion\nwait-for motion\n", "s.txt"));
  runner.start(at(0.0, 0));
  EXPECT_EQ(runner.finish(at(1.0, 40, true, true)), nullptr) << "plan found, motion running";
  ScriptProgress moved = at(2.0, 40, true, true);
  moved.motion_done = true;
  EXPECT_NE(runner.finish(moved), nullptr);
  runner.start(moved);
  ScriptProgress off = at(3.0, 40, true, true);
  off.motion_off = true;
  try {
    runner.finish(off);
    FAIL() << "no failure";
  } catch (const ScriptFailure& f) {
    EXPECT_STREQ(f.what(),
                 "line 2 \"wait-for motion\": the panel computes no motion (--no-motion)");
  }
  ScriptRunner failed(parse_panel_script("wait-for motion\n", "s.txt"));
  failed.start(at(0.0, 0));
  EXPECT_THROW(failed.finish(at(1.0, 9, true, false)), ScriptFailure);
}

TEST(ScriptRunner, MouseActionsAndScreenshotsWaitForTheirFrames) {
  ScriptRunner runner(parse_panel_script("orbit 10 0\n", "s.txt"));
  runner.start(at(0.0, 0));
  ScriptProgress busy = at(0.0, 0);
  busy.frame_work = true;
  EXPECT_EQ(runner.finish(busy), nullptr);
  EXPECT_NE(runner.finish(at(0.1, 0)), nullptr);
}

}  // namespace
}  // namespace stanceplan::gui
