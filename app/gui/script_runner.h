#pragma once
// Carries a panel script (panel_script.h) out over the panel's loop turns: which action starts
// now, and when the one in progress is complete. Waiting actions complete on what the panel
// reports (events published, search finished, a step done, frames drawn); the runner never
// touches the window or the search itself, so its rules are testable without either.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/gui/panel_script.h"

namespace stanceplan::gui {

// What the panel reports to the runner at each loop turn.
struct ScriptProgress {
  double now_s = 0.0;        // seconds on any steady clock
  size_t events = 0;         // events published by the search (of the current run)
  bool finished = false;     // the search ended
  bool found = false;        // ... with a plan
  bool motion_done = false;  // the motion between the plan's steps is computed (every step tried)
  bool motion_off = false;   // the panel computes none (--no-motion)
  bool stepping = false;     // a step expansion / next milestone is still going
  bool frame_work = false;   // pointer moves or a screenshot still to draw
  std::string status;        // "paused", "running", "plan found", "no plan (cancelled)", ...
};

// A waiting action that can no longer complete (wait-for plan after a failure ...).
class ScriptFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ScriptRunner {
 public:
  explicit ScriptRunner(std::vector<ScriptAction> actions) : actions_(std::move(actions)) {}

  // The action to carry out now, or null while the previous one is still in progress (or when
  // the script is over). Each action is handed out once.
  const ScriptAction* start(const ScriptProgress& now);
  // The action in progress, when it is complete now (to be reported), else null. Throws
  // ScriptFailure when it cannot complete any more.
  const ScriptAction* finish(const ScriptProgress& now);
  bool done() const { return next_ >= actions_.size() && !active_; }

 private:
  bool complete(const ScriptAction& action, const ScriptProgress& now) const;

  std::vector<ScriptAction> actions_;
  size_t next_ = 0;
  bool active_ = false;       // actions_[next_ - 1] started and not yet complete
  double started_s_ = 0.0;    // when it started
  size_t events_before_ = 0;  // events when it started
};

// "line 4 \"step event\": 3 events, paused": what the panel prints when an action completes.
std::string script_report(const ScriptAction& action, const ScriptProgress& now);

}  // namespace stanceplan::gui
