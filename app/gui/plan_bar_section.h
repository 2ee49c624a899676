#pragma once
// The bar under the 3-D view. Once a plan is found: a timeline slider over its steps (and through
// the motion between them as it is computed), play / pause, and export of the current view and of
// the strip as PNG. Before: what the search is doing (the newest event); after a failure: why.
#include <string>

#include "app/gui/panel_layout.h"
#include "app/gui/panel_state.h"
#include "app/gui/session_mirror.h"
#include "planner/plan/plan.h"
#include "planner/scene/scene.h"

namespace stanceplan::gui {

// `plan`: the plan found with the motion computed so far (null before).
void draw_plan_bar_section(const Rect& area, const Scene& scene, const SessionMirror& mirror,
                           const Plan* plan, int milestones, PanelState& state);

// Playback: the timeline moves one step every seconds_per_step while playing, through the
// motion between steps where there is one (held on a step where there is none); stops on the last.
void advance_timeline(PanelState& state, int steps, double dt_s);

// The slider's text at the timeline's position: "step 3 of 22", or between two steps
// "step 3 of 22, motion to 4: 5 of 18" (a sample of the motion into step 4).
std::string timeline_label(const Plan& plan, const PanelState& state);

}  // namespace stanceplan::gui
