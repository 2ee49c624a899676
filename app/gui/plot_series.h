#pragma once
// The numbers behind the inspector's plots, taken from the panel's copy of the search: along the
// search, every candidate solve (solver time, iterations, accepted or not) and the milestone the
// search heads for; along the plan found, each step's worst joint torque against its effort limit
// and the vertical force each contact carries. Plain data (no drawing), rebuilt when events
// arrive; every point remembers the event behind it, so that clicking it can select that event.
#include <string>
#include <vector>

#include "app/gui/search_tree.h"
#include "planner/plan/plan.h"
#include "planner/scene/scene.h"

namespace stanceplan::gui {

struct PlotPoint {
  double x = 0.0;
  double y = 0.0;
  long event = -1;   // index in SessionMirror::events() of the event behind the point
  std::string note;  // what the hover readout says besides x and y (may be empty)
};

struct PlotSeries {
  std::string name;  // legend
  std::vector<PlotPoint> points;
};

// Along the search; x is the event number (SearchEvent::number).
struct SearchSeries {
  // One point per Candidate event (the root's solve included), split by outcome.
  PlotSeries accepted_time_ms, rejected_time_ms;
  PlotSeries accepted_iterations, rejected_iterations;
  // The milestone targeted, as a staircase: the first event, each change, the newest event.
  PlotSeries milestone_target;
  // The events that moved it on: each Milestone event, and the PlanFound event at the goal.
  PlotSeries milestones_reached;
};

SearchSeries search_series(const std::vector<SearchEvent>& events);

// Along the plan; x is the step, numbered as in the plan file and the figures (0 = the initial
// stance, render/figures/step_caption.h).
struct PlanSeries {
  std::vector<int> nodes;         // the plan path's node behind each step
  PlotSeries worst_torque_ratio;  // max |tau| / effort per step (note: the joint)
  // Vertical (z) force per contact, one series per contact named anywhere along the plan, in
  // order of first appearance; a step where the contact is absent has no point.
  std::vector<PlotSeries> contact_force_z;
};

// `events` and `tree` as SessionMirror holds them. Step k is the plan path's k-th node, shown as
// the event that made it (what the inspector shows for that step). Steps beyond the tree's plan
// path (which should not happen: the plan is that path) are left out, so every point has an event.
PlanSeries plan_series(const Scene& scene, const std::vector<SearchEvent>& events,
                       const SearchTree& tree, const Plan& plan);

}  // namespace stanceplan::gui
