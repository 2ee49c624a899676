#include "app/gui/search_tree.h"

#include <algorithm>

namespace stanceplan::gui {

const char* to_string(NodeStatus status) {
  switch (status) {
    case NodeStatus::Goal:
      return "goal";
    case NodeStatus::PlanPath:
      return "on the plan";
    case NodeStatus::NoMotion:
      return "no motion";
    case NodeStatus::Milestone:
      return "reached a milestone";
    case NodeStatus::Expanded:
      return "expanded";
    case NodeStatus::Open:
      return "open";
  }
  return "?";
}

void SearchTree::add(const SearchEvent& event, size_t index) {
  switch (event.kind) {
    case SearchEventKind::Candidate:
      if (event.accepted && event.node == static_cast<int>(nodes_.size())) {
        TreeNode n;
        n.id = event.node;
        n.parent = event.parent;
        n.event = index;
        if (const TreeNode* p = node(event.parent)) {
          n.depth = p->depth + 1;
          nodes_[event.parent].children.push_back(n.id);
        }
        nodes_.push_back(n);
      } else if (!event.accepted && node(event.parent) != nullptr) {
        nodes_[event.parent].rejected.push_back(index);
      }
      break;
    case SearchEventKind::Expansion:
      if (node(event.node) != nullptr) ++nodes_[event.node].expansions;
      break;
    case SearchEventKind::Milestone:
      if (node(event.node) != nullptr && !skipped_milestone(event))
        nodes_[event.node].milestone = std::max(nodes_[event.node].milestone, event.milestone);
      break;
    case SearchEventKind::PlanFound:
      goal_ = event.node;
      for (int i = goal_; node(i) != nullptr; i = nodes_[i].parent) nodes_[i].on_plan = true;
      break;
    case SearchEventKind::Failure:
      closest_ = event.node;
      break;
    case SearchEventKind::MotionFailed:
      if (node(event.node) != nullptr) {
        nodes_[event.node].motion_failed = static_cast<long>(index);
        drop(event.node);
      }
      break;
  }
}

void SearchTree::drop(int id) {
  nodes_[id].dropped = true;
  for (int child : nodes_[id].children) drop(child);
}

const TreeNode* SearchTree::node(int id) const {
  return id >= 0 && id < static_cast<int>(nodes_.size()) ? &nodes_[id] : nullptr;
}

NodeStatus SearchTree::status(int id) const {
  const TreeNode& n = nodes_.at(id);
  if (id == goal_) return NodeStatus::Goal;
  if (n.on_plan) return NodeStatus::PlanPath;
  if (n.dropped) return NodeStatus::NoMotion;
  if (n.milestone >= 0) return NodeStatus::Milestone;
  if (n.expansions > 0) return NodeStatus::Expanded;
  return NodeStatus::Open;
}

std::vector<int> SearchTree::plan_path() const {
  std::vector<int> path;
  for (int i = goal_; node(i) != nullptr; i = nodes_[i].parent) path.push_back(i);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace stanceplan::gui
