#include "app/gui/search_driver.h"

#include <algorithm>
#include <cmath>

namespace stanceplan::gui {

const char* to_string(RunMode mode) {
  switch (mode) {
    case RunMode::Running:
      return "running";
    case RunMode::Paused:
      return "paused";
    case RunMode::UntilExpansion:
      return "to the next expansion";
    case RunMode::UntilMilestone:
      return "to the next milestone";
  }
  return "?";
}

SearchDriver::SearchDriver(StepGate& gate, bool paused)
    : gate_(gate), mode_(paused ? RunMode::Paused : RunMode::Running), gate_paused_(false) {
  if (paused) apply_pause();
}

void SearchDriver::step_event() {
  mode_ = RunMode::Paused;
  ++pending_steps_;
}

void SearchDriver::step_expansion() {
  mode_ = RunMode::UntilExpansion;
}

void SearchDriver::next_milestone() {
  mode_ = RunMode::UntilMilestone;
}

void SearchDriver::restarted() {
  if (mode_ != RunMode::Running) mode_ = RunMode::Paused;
  outstanding_ = 0;
  pending_steps_ = 0;
  credit_ = 0.0;
}

void SearchDriver::apply_pause() {
  gate_.pause();  // also drops any budget not yet used
  gate_paused_ = true;
  outstanding_ = 0;
}

void SearchDriver::update(const std::vector<SearchEventKind>& arrived, double dt_s) {
  outstanding_ = std::max(0, outstanding_ - static_cast<int>(arrived.size()));
  if (mode_ == RunMode::UntilExpansion || mode_ == RunMode::UntilMilestone) {
    const SearchEventKind wanted =
        mode_ == RunMode::UntilExpansion ? SearchEventKind::Expansion : SearchEventKind::Milestone;
    // Events that were already on their way when the mode was chosen count too.
    if (std::find(arrived.begin(), arrived.end(), wanted) != arrived.end()) mode_ = RunMode::Paused;
  }
  switch (mode_) {
    case RunMode::Paused:
      if (!gate_paused_) apply_pause();
      if (pending_steps_ > 0) {
        gate_.step(pending_steps_);
        outstanding_ += pending_steps_;
        pending_steps_ = 0;
      }
      break;
    case RunMode::UntilExpansion:
    case RunMode::UntilMilestone:
      if (!gate_paused_) apply_pause();
      if (outstanding_ == 0) {  // one event at a time, so that the wanted one is the last
        gate_.step(1);
        outstanding_ = 1;
      }
      break;
    case RunMode::Running:
      if (limit_ <= 0.0) {
        if (gate_paused_) gate_.resume();
        gate_paused_ = false;
        outstanding_ = 0;
        credit_ = 0.0;
        break;
      }
      if (!gate_paused_) apply_pause();
      // Earned events accumulate only while the search keeps up (at most a fifth of a second's
      // worth), so that a slow stretch is not followed by a burst.
      credit_ = std::min(credit_ + limit_ * dt_s, std::max(1.0, 0.2 * limit_));
      if (outstanding_ == 0 && credit_ >= 1.0) {
        const int grant = static_cast<int>(std::floor(credit_));
        gate_.step(grant);
        outstanding_ = grant;
        credit_ -= grant;
      }
      break;
  }
}

}  // namespace stanceplan::gui
