#pragma once
// The bar under the 3-D view. Once a plan is found: a timeline slider over its steps, play /
// pause, and export of the current view and of the strip as PNG. Before: what the search is
// doing (the newest event); after a failure: why.
#include "app/gui/panel_layout.h"
#include "app/gui/panel_state.h"
#include "app/gui/session_mirror.h"
#include "planner/scene/scene.h"

namespace stanceplan::gui {

void draw_plan_bar_section(const Rect& area, const Scene& scene, const SessionMirror& mirror,
                           int milestones, PanelState& state);

// Playback: moves to the next step every seconds_per_step while playing; stops on the last.
void advance_timeline(PanelState& state, int steps, double dt_s);

}  // namespace stanceplan::gui
