#include "planner/search/plan_path.h"

#include <algorithm>

namespace stanceplan {

Plan plan_to_node(const std::vector<SearchNode>& tree, int node) {
  std::vector<int> path;
  for (int i = node; i >= 0; i = tree[i].parent) path.push_back(i);
  std::reverse(path.begin(), path.end());
  Plan plan;
  for (int i : path) plan.steps.push_back(tree[i].step);
  return plan;
}

}  // namespace stanceplan
