#pragma once
// The search tree's list as rows to draw, worked out without ImGui (so it is tested alone): the
// tree in depth-first order, each row indented by its node's depth, so a parent is always
// exactly one level left of its children and siblings are level, however the tree branches; or,
// filtered, a flat list (the plan path, the nodes that reached a milestone, every rejected
// candidate). Collapsing a node hides its subtree; a node's rejected candidates are folded under
// one "N rejected" row, closed until opened. Fold flags are kept by node id in plain vectors
// (PanelState holds them); ids past the end of a vector keep the default.
#include <cstddef>
#include <vector>

#include "app/gui/search_tree.h"

namespace stanceplan::gui {

enum class TreeFilter { All, OnPlan, Milestones, Rejected };
inline constexpr int kTreeFilterCount = 4;
const char* to_string(TreeFilter filter);

enum class RowKind {
  Node,           // a node of the tree
  RejectedGroup,  // "N rejected": the candidates tried from `node` and not accepted
  Rejected,       // one of them
};

struct TreeRow {
  RowKind kind = RowKind::Node;
  int node = -1;          // the node; for the other kinds, the node the candidates were tried from
  size_t event = 0;       // Node: the event that made it; Rejected: the candidate's event
  int indent = 0;         // in levels; 0 for every row of a filtered (flat) list
  bool foldable = false;  // the tree view has something under it to hide or show
  bool folded = false;    // and it is hidden
};

// The fold flag of a node (false past the end), and setting it (the vector grows as needed).
bool fold_flag(const std::vector<bool>& flags, int node);
void set_fold_flag(std::vector<bool>& flags, int node, bool value);

// The rows to draw. `collapsed`: nodes whose subtree is hidden; `rejected_open`: nodes whose
// rejected candidates are listed. Both only matter to the whole tree (TreeFilter::All).
std::vector<TreeRow> tree_rows(const SearchTree& tree, TreeFilter filter,
                               const std::vector<bool>& collapsed,
                               const std::vector<bool>& rejected_open);

// Opens the collapsed ancestors of `node` so that the whole tree lists it (the node itself stays
// as it is); returns whether any was collapsed.
bool expand_ancestors(const SearchTree& tree, int node, std::vector<bool>& collapsed);

// The row of a node (kind Node), or of a rejected candidate's event (kind Rejected); -1 when the
// rows do not list it (filtered out, or under a collapsed node: expand_ancestors first).
int node_row(const std::vector<TreeRow>& rows, int node);
int rejected_row(const std::vector<TreeRow>& rows, size_t event);

// The connector lines left of a row of the whole tree, which tie each row to its parent even when
// they are many rows apart. Levels are indents: a vertical line at level L runs below the row
// of indent L that it comes from.
struct RowGuides {
  std::vector<int> through;  // levels whose line passes this row (an ancestor has more below)
  int elbow = -1;            // the parent's level, whose line turns right into this row (-1: none)
  bool elbow_goes_on = false;  // the parent has more rows under it below this one
};
RowGuides row_guides(const SearchTree& tree, const TreeRow& row);

}  // namespace stanceplan::gui
