#include "app/gui/tree_rows.h"

namespace stanceplan::gui {
namespace {

bool has_under(const TreeNode& n) {
  return !n.children.empty() || !n.rejected.empty();
}

// A node's "N rejected" row and, when opened, its candidates one level further in.
void append_rejected(const TreeNode& n, const std::vector<bool>& rejected_open,
                     std::vector<TreeRow>& rows) {
  if (n.rejected.empty()) return;
  const bool open = fold_flag(rejected_open, n.id);
  rows.push_back({RowKind::RejectedGroup, n.id, 0, n.depth + 1, true, !open});
  if (!open) return;
  for (size_t event : n.rejected)
    rows.push_back({RowKind::Rejected, n.id, event, n.depth + 2, false, false});
}

// The whole tree, depth first with an explicit stack: a best-first search grows chains thousands
// of nodes deep, too deep for recursion. Under each node come its rejected candidates, then its
// children in creation order.
void append_tree(const SearchTree& tree, const std::vector<bool>& collapsed,
                 const std::vector<bool>& rejected_open, std::vector<TreeRow>& rows) {
  if (tree.node(0) == nullptr) return;
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const TreeNode& n = *tree.node(stack.back());
    stack.pop_back();
    const bool folded = has_under(n) && fold_flag(collapsed, n.id);
    rows.push_back({RowKind::Node, n.id, n.event, n.depth, has_under(n), folded});
    if (folded) continue;
    append_rejected(n, rejected_open, rows);
    for (auto child = n.children.rbegin(); child != n.children.rend(); ++child)
      stack.push_back(*child);
  }
}

// The nodes in depth-first order, ignoring folds: the order the flat lists keep.
std::vector<int> depth_first(const SearchTree& tree) {
  std::vector<int> order;
  if (tree.node(0) == nullptr) return order;
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const TreeNode& n = *tree.node(stack.back());
    stack.pop_back();
    order.push_back(n.id);
    for (auto child = n.children.rbegin(); child != n.children.rend(); ++child)
      stack.push_back(*child);
  }
  return order;
}

TreeRow flat_node_row(const TreeNode& n) {
  return {RowKind::Node, n.id, n.event, 0, false, false};
}

}  // namespace

const char* to_string(TreeFilter filter) {
  switch (filter) {
    case TreeFilter::All:
      return "All nodes";
    case TreeFilter::OnPlan:
      return "On the plan";
    case TreeFilter::Milestones:
      return "Milestones";
    case TreeFilter::Rejected:
      return "Rejected";
  }
  return "?";
}

bool fold_flag(const std::vector<bool>& flags, int node) {
  return node >= 0 && node < static_cast<int>(flags.size()) && flags[node];
}

void set_fold_flag(std::vector<bool>& flags, int node, bool value) {
  if (node < 0) return;
  if (node >= static_cast<int>(flags.size())) {
    if (!value) return;  // already the default
    flags.resize(node + 1, false);
  }
  flags[node] = value;
}

std::vector<TreeRow> tree_rows(const SearchTree& tree, TreeFilter filter,
                               const std::vector<bool>& collapsed,
                               const std::vector<bool>& rejected_open) {
  std::vector<TreeRow> rows;
  switch (filter) {
    case TreeFilter::All:
      append_tree(tree, collapsed, rejected_open, rows);
      break;
    case TreeFilter::OnPlan:  // root first: row k is plan step k
      for (int id : tree.plan_path()) rows.push_back(flat_node_row(*tree.node(id)));
      break;
    case TreeFilter::Milestones:
      for (int id : depth_first(tree))
        if (tree.node(id)->milestone >= 0) rows.push_back(flat_node_row(*tree.node(id)));
      break;
    case TreeFilter::Rejected:
      for (int id : depth_first(tree))
        for (size_t event : tree.node(id)->rejected)
          rows.push_back({RowKind::Rejected, id, event, 0, false, false});
      break;
  }
  return rows;
}

bool expand_ancestors(const SearchTree& tree, int node, std::vector<bool>& collapsed) {
  bool changed = false;
  const TreeNode* n = tree.node(node);
  for (int a = n ? n->parent : -1; tree.node(a) != nullptr; a = tree.node(a)->parent) {
    if (!fold_flag(collapsed, a)) continue;
    set_fold_flag(collapsed, a, false);
    changed = true;
  }
  return changed;
}

int node_row(const std::vector<TreeRow>& rows, int node) {
  for (size_t i = 0; i < rows.size(); ++i)
    if (rows[i].kind == RowKind::Node && rows[i].node == node) return static_cast<int>(i);
  return -1;
}

int rejected_row(const std::vector<TreeRow>& rows, size_t event) {
  for (size_t i = 0; i < rows.size(); ++i)
    if (rows[i].kind == RowKind::Rejected && rows[i].event == event) return static_cast<int>(i);
  return -1;
}

RowGuides row_guides(const SearchTree& tree, const TreeRow& row) {
  RowGuides g;
  const TreeNode* n = tree.node(row.node);
  if (n == nullptr) return g;
  // The row's own parent: a node's parent node, the group's node, or a candidate's group.
  if (row.kind == RowKind::Rejected) {
    g.elbow = n->depth + 1;
    g.elbow_goes_on = row.event != n->rejected.back();
    if (!n->children.empty()) g.through.push_back(n->depth);  // the group's node goes on below
  } else if (row.kind == RowKind::RejectedGroup) {
    g.elbow = n->depth;
    g.elbow_goes_on = !n->children.empty();  // the group comes before the children
  } else if (const TreeNode* p = tree.node(n->parent)) {
    g.elbow = p->depth;
    g.elbow_goes_on = n->id != p->children.back();
  }
  // Further up, an ancestor's line passes the row while that ancestor has a child below it.
  const TreeNode* c = row.kind == RowKind::Node ? tree.node(n->parent) : n;
  for (; c != nullptr && tree.node(c->parent) != nullptr; c = tree.node(c->parent)) {
    const TreeNode& a = *tree.node(c->parent);
    if (c->id != a.children.back()) g.through.push_back(a.depth);
  }
  return g;
}

}  // namespace stanceplan::gui
