#pragma once
// The panel's search controls turned into step-gate calls (planner/search/search_events.h):
// run, pause, step one event, step to the next expansion, continue to the next milestone, and a
// speed limit in events per second. The gate holds the search before each event is published, so
// "until" modes let events through one at a time and stop on the first one of the wanted kind:
// they never overshoot. Called from the panel's thread once per frame; no window, no GL.
#include <cstddef>
#include <vector>

#include "planner/search/search_events.h"

namespace stanceplan::gui {

enum class RunMode { Running, Paused, UntilExpansion, UntilMilestone };
const char* to_string(RunMode mode);

class SearchDriver {
 public:
  // Holds `gate` (which must outlive the driver); pauses it at once when `paused`.
  SearchDriver(StepGate& gate, bool paused);

  void run() { mode_ = RunMode::Running; }
  void pause() { mode_ = RunMode::Paused; }
  void step_event();      // pauses, then lets exactly one event through
  void step_expansion();  // lets events through up to and including the next expansion
  void next_milestone();  // lets events through up to and including the next milestone
  // Events per second while running; 0 (or less) removes the limit.
  void set_speed_limit(double events_per_s) { limit_ = events_per_s > 0.0 ? events_per_s : 0.0; }
  double speed_limit() const { return limit_; }
  RunMode mode() const { return mode_; }
  // The session restarted its search on the same gate: grants and credit of the old search are
  // void; a step in progress ends paused.
  void restarted();

  // Once per frame: the kinds of the events published since the previous call, in order, and the
  // seconds elapsed. Applies the mode to the gate.
  void update(const std::vector<SearchEventKind>& arrived, double dt_s);

 private:
  void apply_pause();

  StepGate& gate_;
  RunMode mode_;
  bool gate_paused_;       // whether the gate holds the search (pause() or step() last applied)
  int outstanding_ = 0;    // events granted with step() and not yet seen
  int pending_steps_ = 0;  // single steps asked for and not yet granted
  double limit_ = 0.0;
  double credit_ = 0.0;  // events earned under the speed limit and not yet granted
};

}  // namespace stanceplan::gui
