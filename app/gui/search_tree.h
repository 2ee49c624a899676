#pragma once
// The search tree as the panel shows it, rebuilt from the search's events alone (the planner's
// own tree is only handed over at the end): nodes with their parent, the event that made them,
// whether they were expanded, the milestones they reached, the rejected candidates tried from them,
// and the plan path once found. Plain data; the tree view draws it.
#include <cstddef>
#include <vector>

#include "planner/search/search_events.h"

namespace stanceplan::gui {

// What a node's colour says, from the most to the least specific.
// NoMotion: the transition that made the node (or an ancestor's) has no motion (MotionFailed).
enum class NodeStatus { Goal, PlanPath, NoMotion, Milestone, Expanded, Open };
const char* to_string(NodeStatus status);

struct TreeNode {
  int id = 0;
  int parent = -1;
  int depth = 0;
  size_t event = 0;              // index of the accepted candidate event that made it
  std::vector<int> children;     // node ids, in creation order
  std::vector<size_t> rejected;  // indices of the candidate events from this node not accepted
  int expansions = 0;            // times popped from the open queue (0 or 1; retries re-expand)
  int milestone = -1;            // highest milestone index this node made the search reach
  bool on_plan = false;
  bool dropped = false;     // no motion into it or into an ancestor (SearchNode::dropped)
  long motion_failed = -1;  // index of the MotionFailed event that dropped it (-1: none, or an
                            // ancestor's)
};

class SearchTree {
 public:
  // Events must come in order, each once (`index` is its position in the event stream).
  void add(const SearchEvent& event, size_t index);

  const std::vector<TreeNode>& nodes() const { return nodes_; }
  const TreeNode* node(int id) const;
  NodeStatus status(int id) const;
  int goal() const { return goal_; }
  int closest() const { return closest_; }  // after a failure: the node closest to the goal
  // The plan path, root first (empty until a plan is found).
  std::vector<int> plan_path() const;

 private:
  void drop(int id);  // the node and its subtree
  std::vector<TreeNode> nodes_;
  int goal_ = -1;
  int closest_ = -1;
};

}  // namespace stanceplan::gui
