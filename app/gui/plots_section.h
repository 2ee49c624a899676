#pragma once
// Plots of the search and of the plan found, drawn in the inspector's "Plots" tab.
#include "app/gui/panel_state.h"
#include "app/gui/session_mirror.h"
#include "planner/plan/plan.h"
#include "planner/scene/scene.h"

namespace stanceplan::gui {

// `plan`: the plan found, or null while the search runs / after a failure.
void draw_plots_section(const Scene& scene, const SessionMirror& mirror, const Plan* plan,
                        PanelState& state);

}  // namespace stanceplan::gui
