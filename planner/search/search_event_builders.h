#pragma once
// The events StanceSearch publishes, built from what they report (search_events.h says what each
// field means for each kind).
#include <string>

#include "planner/search/search_events.h"
#include "planner/search/stance_search.h"

namespace stanceplan {

// A milestone reached or the plan found at `node`.
SearchEvent node_event(SearchEventKind kind, const SearchNode& node, int milestone, int nodes);
// The expansion of `node`, with the figures of the solve that made it.
SearchEvent expansion_event(const SearchNode& node, int milestone, int nodes);
// The root realised: the initial stance's solve, accepted as node 0.
SearchEvent root_event(const SearchNode& root, const PostureResult& solved);
// A candidate solve from node `parent` towards `stance`: what was asked and what came back
// (accepted, node, milestone and nodes are the caller's to set).
SearchEvent candidate_event(int parent, const Stance& stance, bool add, const Contact& changed,
                            const PostureRequest& request, const PostureResult& solved);
// The search ended without a plan: why, and the closest node (-1: none).
SearchEvent failure_event(const std::string& message, const std::vector<SearchNode>& tree,
                          int closest);

}  // namespace stanceplan
