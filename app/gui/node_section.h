#pragma once
// The inspector of what the view shows (a node, a rejected candidate, a plan step): its change of
// contact, the solver's status, iterations, time and worst residuals, the contacts (loaded or
// not) with their forces, and every joint torque as a bar against its effort limit (E19).
#include <string>

#include "app/gui/node_details.h"
#include "app/gui/panel_state.h"
#include "app/gui/session_mirror.h"
#include "planner/scene/scene.h"

namespace stanceplan::gui {

// `shown` indexes mirror.events() (-1: nothing to show yet); `title` names it ("Node 12");
// `tolerance`: the solver's constraint tolerance, which the residuals are shown against.
void draw_node_section(const Scene& scene, const SessionMirror& mirror, long shown,
                       const std::string& title, double tolerance, PanelState& state);

}  // namespace stanceplan::gui
