#pragma once
// Everything the panel remembers between frames, as one plain struct: what the 3-D view shows,
// the selection, the timeline, and requests raised by buttons for the frame loop to carry out.
// The sections read and write it; they hold no state of their own.
#include <string>
#include <vector>

#include "app/gui/panel_layout.h"

namespace stanceplan::gui {

// What the 3-D view and the inspector show.
enum class ViewSource {
  Latest,    // the newest event with a configuration (follows the search)
  Node,      // the selected node (the candidate event that made it)
  Event,     // one chosen event (a rejected candidate: the solver's final iterate)
  PlanStep,  // a step of the plan found (the timeline)
};

struct PanelState {
  ViewSource source = ViewSource::Latest;
  int selected_node = -1;
  long selected_event = -1;
  int tree_focus = -1;        // the node the tree keeps in sight: the selection, or the newest
  bool reveal_focus = false;  // the focus changed: open its ancestors and scroll to it

  // Timeline over the plan found: at position plan_step + step_fraction (planner/plan/
  // plan_timeline.h), step_fraction in [0, 1) the way through the motion into the next step.
  int plan_step = 0;
  double step_fraction = 0.0;
  bool playing = false;
  float seconds_per_step = 1.0f;

  float speed_limit = 0.0f;  // events per second while running; 0: none

  // The search tree's view.
  int tree_filter = 0;                   // a TreeFilter (tree_rows.h): what the list shows
  std::vector<bool> tree_collapsed;      // by node id: the node's subtree is hidden
  std::vector<bool> tree_rejected_open;  // by node id: its rejected candidates are listed
  int tree_focus_row = -1;  // the focused node's row last frame: the list scrolls as it moves

  // Raised by buttons, carried out (and cleared) by the frame loop.
  bool export_view = false;
  bool export_strip = false;
  bool cancel_search = false;
  bool reset_camera = false;
  bool rerun = false;           // a new search from the start (after a failure or a cancel)
  bool show_closest = false;    // view the node closest to the goal (after a failure)
  bool export_partial = false;  // write the plan to the closest node (after a failure)
  int open_tab = -1;            // the inspector's tab to bring forward (0 inspector, 1 plots)
  std::string export_folder = ".";
  Rect reset_button;  // where the view's Reset view button was drawn (scripted clicks)

  std::vector<std::string> messages;  // export results and warnings, newest last
};

// The view and the timeline on a step of the plan (its posture, not a sample of a motion).
inline void show_plan_step(PanelState& state, int step) {
  state.source = ViewSource::PlanStep;
  state.plan_step = step;
  state.step_fraction = 0.0;
}

}  // namespace stanceplan::gui
