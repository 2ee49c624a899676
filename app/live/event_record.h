#pragma once
// How one search event is named and described outside the program: the snapshot's file name, the
// caption drawn on it, and its line of events.jsonl. Pure functions of the event and the scene.
#include <string>

#include "planner/scene/scene.h"
#include "planner/search/search_events.h"

namespace stanceplan::app {

// "event_00012_candidate.png": the event number (5 digits, so names sort in event order) and kind.
std::string snapshot_file_name(const SearchEvent& event);
// "add l_hand on desk_top", "remove l_sole from floor", "" when the event changes no contact.
std::string event_change(const Scene& scene, const SearchEvent& event);
// Three lines for the snapshot: "Event 12 · candidate · add l_hand on desk_top" (bold), the
// outcome ("solved, accepted, node 7 · 35.2 ms" / "infeasible, rejected: ...") and the stance.
std::string event_caption(const Scene& scene, const SearchEvent& event, int milestones);
// One line of events.jsonl (no trailing newline): number, kind, node, parent, stance (pairs of
// surface ids), change, status, accepted, message, solve time, time since the search started,
// milestone, tree size, image (file name, or null when no snapshot was made).
std::string event_json_line(const Scene& scene, const SearchEvent& event, double time_s,
                            const std::string& image);

}  // namespace stanceplan::app
