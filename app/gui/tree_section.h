#pragma once
// The search tree as a list (rows from tree_rows.h, drawn with ImGui's list clipper so thousands
// of nodes stay fast): every node coloured by its status (ui_style.h), indented by its depth with
// guide lines to its parent, with its change of contact; under each node the candidates tried
// from it and rejected. A filter shows instead the plan path, the milestones or every rejected
// candidate. Clicking a node or a rejected candidate selects it for the 3-D view and the
// inspector; the focused node is kept in sight.
#include "app/gui/panel_state.h"
#include "app/gui/session_mirror.h"
#include "planner/scene/scene.h"

namespace stanceplan::gui {

void draw_tree_section(const Scene& scene, const SessionMirror& mirror, PanelState& state);

// Selects a node: the view and the inspector show it, and the tree opens down to it.
void select_node(PanelState& state, int node);

}  // namespace stanceplan::gui
