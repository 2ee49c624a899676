#pragma once
// The search controls: run, pause, step one event, step to the next expansion, continue to the
// next milestone, cancel, and the speed limit; then one status line (mode, events, nodes,
// milestone, elapsed time).
#include "app/gui/panel_state.h"
#include "app/gui/search_driver.h"
#include "app/gui/session_mirror.h"

namespace stanceplan::gui {

struct SearchFigures {
  int milestones = 0;            // in the scenario
  double elapsed_s = 0.0;        // since the search started (frozen when it finished)
  const Stance* goal = nullptr;  // the goal stance: the status names the node closest to it
};

void draw_controls_section(SearchDriver& driver, const SessionMirror& mirror,
                           const SearchFigures& figures, PanelState& state);

}  // namespace stanceplan::gui
