#pragma once
// The plan along the search tree from the root to one node: the found plan (node = the goal) or,
// when no plan is found, the partial plan to the node closest to the goal (`plan --partial`).
#include <vector>

#include "planner/plan/plan.h"
#include "planner/search/stance_search.h"

namespace stanceplan {

// Steps of the nodes from the root to `node`, in order (stats left empty).
Plan plan_to_node(const std::vector<SearchNode>& tree, int node);

}  // namespace stanceplan
