// tree_rows: the search tree's list as rows (indentation, folds, filters, focus, guide lines).
#include "app/gui/tree_rows.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "tests/support/search_event_fakes.h"

namespace stanceplan::gui {
namespace {

using test::candidate;
using test::of_kind;

// The report's "#2 after #33": A (0) has children B (1) and E (4); B has the chain C (2), D (3).
// Rejected from A: event 2; from C: events 5 and 6. D reaches milestone 1, E milestone 0; the plan
// ends at D.
SearchTree branching_tree() {
  const std::vector<SearchEvent> events = {candidate(-1, 0, true),
                                           candidate(0, 1, true),
                                           candidate(0, -1, false),
                                           candidate(1, 2, true),
                                           candidate(2, 3, true),
                                           candidate(2, -1, false),
                                           candidate(2, -1, false),
                                           candidate(0, 4, true),
                                           of_kind(SearchEventKind::Milestone, 3, 1),
                                           of_kind(SearchEventKind::Milestone, 4, 0),
                                           of_kind(SearchEventKind::PlanFound, 3)};
  SearchTree tree;
  for (size_t i = 0; i < events.size(); ++i) tree.add(events[i], i);
  return tree;
}

std::vector<int> node_ids(const std::vector<TreeRow>& rows) {
  std::vector<int> ids;
  for (const TreeRow& r : rows)
    if (r.kind == RowKind::Node) ids.push_back(r.node);
  return ids;
}

// Reading an indented list, a row's parent is the nearest row above it that is less indented.
// That reading must give the tree's parent for every node, and the parent one level left.
void expect_indentation_shows_parents(const SearchTree& tree, const std::vector<TreeRow>& rows) {
  for (size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].kind != RowKind::Node || tree.node(rows[i].node)->parent < 0) continue;
    int above = static_cast<int>(i) - 1;
    while (above >= 0 && rows[above].indent >= rows[i].indent) --above;
    ASSERT_GE(above, 0) << "node " << rows[i].node << " has no less indented row above";
    EXPECT_EQ(rows[above].kind, RowKind::Node);
    EXPECT_EQ(rows[above].node, tree.node(rows[i].node)->parent) << "row of node " << rows[i].node;
    EXPECT_EQ(rows[i].indent, rows[above].indent + 1);
  }
}

const std::vector<bool> kNone;

TEST(TreeRows, ListsTheTreeDepthFirstWithParentsLeftOfTheirChildren) {
  const SearchTree tree = branching_tree();
  const std::vector<TreeRow> rows = tree_rows(tree, TreeFilter::All, kNone, kNone);
  EXPECT_EQ(node_ids(rows), (std::vector<int>{0, 1, 2, 3, 4}));
  ASSERT_EQ(rows.size(), 7u);  // and the closed "rejected" rows of A and C
  EXPECT_EQ(rows[1].kind, RowKind::RejectedGroup);
  EXPECT_EQ(rows[1].node, 0);
  EXPECT_EQ(rows[4].kind, RowKind::RejectedGroup);
  EXPECT_EQ(rows[4].node, 2);
  // D (deep in B's chain) is listed just before E, but further right than E and than B.
  EXPECT_EQ(rows[5].node, 3);
  EXPECT_EQ(rows[6].node, 4);
  EXPECT_GT(rows[5].indent, rows[6].indent);
  EXPECT_EQ(rows[6].indent, rows[2].indent);  // E level with its sibling B
  expect_indentation_shows_parents(tree, rows);
}

TEST(TreeRows, AnOpenedRejectedGroupListsItsCandidatesUnderIt) {
  const SearchTree tree = branching_tree();
  std::vector<bool> open;
  set_fold_flag(open, 2, true);
  const std::vector<TreeRow> rows = tree_rows(tree, TreeFilter::All, kNone, open);
  ASSERT_EQ(rows.size(), 9u);
  EXPECT_FALSE(rows[4].folded);
  EXPECT_EQ(rows[5].kind, RowKind::Rejected);
  EXPECT_EQ(rows[5].event, 5u);
  EXPECT_EQ(rows[6].event, 6u);
  EXPECT_EQ(rows[5].indent, rows[4].indent + 1);
  EXPECT_EQ(rows[7].node, 3);  // the candidates come before C's children
  expect_indentation_shows_parents(tree, rows);
}

TEST(TreeRows, CollapsingANodeHidesItsSubtreeOnly) {
  const SearchTree tree = branching_tree();
  std::vector<bool> collapsed;
  set_fold_flag(collapsed, 1, true);
  std::vector<TreeRow> rows = tree_rows(tree, TreeFilter::All, collapsed, kNone);
  EXPECT_EQ(node_ids(rows), (std::vector<int>{0, 1, 4}));
  EXPECT_TRUE(rows[node_row(rows, 1)].folded);
  EXPECT_FALSE(rows[node_row(rows, 4)].folded);
  set_fold_flag(collapsed, 0, true);
  rows = tree_rows(tree, TreeFilter::All, collapsed, kNone);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_TRUE(rows[0].folded);
  // A leaf has nothing to fold: marking it collapsed changes nothing.
  std::vector<bool> leaf;
  set_fold_flag(leaf, 3, true);
  rows = tree_rows(tree, TreeFilter::All, leaf, kNone);
  EXPECT_EQ(rows.size(), 7u);
  EXPECT_FALSE(rows[node_row(rows, 3)].foldable);
  EXPECT_FALSE(rows[node_row(rows, 3)].folded);
}

TEST(TreeRows, FiltersGiveFlatLists) {
  const SearchTree tree = branching_tree();
  std::vector<bool> collapsed;
  set_fold_flag(collapsed, 0, true);  // folds matter only to the whole tree
  const auto plan = tree_rows(tree, TreeFilter::OnPlan, collapsed, kNone);
  EXPECT_EQ(node_ids(plan), (std::vector<int>{0, 1, 2, 3}));
  const auto milestones = tree_rows(tree, TreeFilter::Milestones, collapsed, kNone);
  EXPECT_EQ(node_ids(milestones), (std::vector<int>{3, 4}));
  const auto rejected = tree_rows(tree, TreeFilter::Rejected, collapsed, kNone);
  ASSERT_EQ(rejected.size(), 3u);
  EXPECT_EQ(rejected[0].event, 2u);
  EXPECT_EQ(rejected[0].node, 0);  // tried from A
  EXPECT_EQ(rejected[1].event, 5u);
  EXPECT_EQ(rejected[2].event, 6u);
  EXPECT_EQ(rejected[2].node, 2);  // tried from C
  for (const auto* list : {&plan, &milestones, &rejected})
    for (const TreeRow& r : *list) {
      EXPECT_EQ(r.indent, 0);
      EXPECT_FALSE(r.foldable);
    }
  for (const auto& r : rejected) EXPECT_EQ(r.kind, RowKind::Rejected);
}

TEST(TreeRows, AnEmptyTreeHasNoRows) {
  const SearchTree tree;
  for (int f = 0; f < kTreeFilterCount; ++f)
    EXPECT_TRUE(tree_rows(tree, static_cast<TreeFilter>(f), kNone, kNone).empty());
  SearchTree unplanned;
  unplanned.add(candidate(-1, 0, true), 0);
  EXPECT_TRUE(tree_rows(unplanned, TreeFilter::OnPlan, kNone, kNone).empty());
}

TEST(TreeRows, RevealingAFocusedNodeOpensItsAncestorsOnly) {
  const SearchTree tree = branching_tree();
  std::vector<bool> collapsed;
  set_fold_flag(collapsed, 1, true);
  set_fold_flag(collapsed, 2, true);
  EXPECT_EQ(node_row(tree_rows(tree, TreeFilter::All, collapsed, kNone), 3), -1);
  EXPECT_TRUE(expand_ancestors(tree, 2, collapsed));
  EXPECT_FALSE(fold_flag(collapsed, 1));
  EXPECT_TRUE(fold_flag(collapsed, 2));  // the node itself stays folded
  EXPECT_TRUE(expand_ancestors(tree, 3, collapsed));
  const auto rows = tree_rows(tree, TreeFilter::All, collapsed, kNone);
  EXPECT_EQ(node_row(rows, 3), 5);
  EXPECT_EQ(node_row(rows, 4), 6);
  EXPECT_FALSE(expand_ancestors(tree, 3, collapsed));  // nothing left to open
  EXPECT_FALSE(expand_ancestors(tree, 99, collapsed));
  EXPECT_EQ(node_row(tree_rows(tree, TreeFilter::Milestones, collapsed, kNone), 4), 1);
  EXPECT_EQ(node_row(tree_rows(tree, TreeFilter::OnPlan, collapsed, kNone), 4), -1);
  EXPECT_EQ(rejected_row(tree_rows(tree, TreeFilter::Rejected, kNone, kNone), 6), 2);
  EXPECT_EQ(rejected_row(rows, 6), -1);  // its group is closed
}

TEST(TreeRows, GuideLinesTieEachRowToItsParent) {
  const SearchTree tree = branching_tree();
  std::vector<bool> open;
  set_fold_flag(open, 2, true);
  const auto rows = tree_rows(tree, TreeFilter::All, kNone, open);
  const RowGuides b = row_guides(tree, rows[node_row(rows, 1)]);
  EXPECT_EQ(b.elbow, 0);
  EXPECT_TRUE(b.elbow_goes_on);  // A's line goes on down to E
  const RowGuides d = row_guides(tree, rows[node_row(rows, 3)]);
  EXPECT_EQ(d.elbow, 2);
  EXPECT_FALSE(d.elbow_goes_on);
  EXPECT_EQ(d.through, (std::vector<int>{0}));  // A's line passes D on its way to E
  const RowGuides e = row_guides(tree, rows[node_row(rows, 4)]);
  EXPECT_EQ(e.elbow, 0);
  EXPECT_FALSE(e.elbow_goes_on);
  EXPECT_TRUE(e.through.empty());
  const RowGuides first = row_guides(tree, rows[rejected_row(rows, 5)]);
  EXPECT_EQ(first.elbow, 3);  // from the "2 rejected" row
  EXPECT_TRUE(first.elbow_goes_on);
  std::vector<int> levels = first.through;
  std::sort(levels.begin(), levels.end());
  EXPECT_EQ(levels, (std::vector<int>{0, 2}));  // C goes on to D, A to E
  EXPECT_FALSE(row_guides(tree, rows[rejected_row(rows, 6)]).elbow_goes_on);
  EXPECT_EQ(row_guides(tree, rows[0]).elbow, -1);  // the root
}

TEST(TreeRows, ADeepChainIsListedWithoutRecursion) {
  SearchTree tree;
  tree.add(candidate(-1, 0, true), 0);
  const int depth = 20000;
  for (int i = 1; i <= depth; ++i) tree.add(candidate(i - 1, i, true), size_t(i));
  const auto rows = tree_rows(tree, TreeFilter::All, kNone, kNone);
  ASSERT_EQ(rows.size(), size_t(depth + 1));
  EXPECT_EQ(rows.back().indent, depth);
  expect_indentation_shows_parents(tree, rows);
}

TEST(TreeRows, FoldFlagsDefaultToFalseAndGrow) {
  std::vector<bool> flags;
  EXPECT_FALSE(fold_flag(flags, 5));
  EXPECT_FALSE(fold_flag(flags, -1));
  set_fold_flag(flags, 5, false);
  EXPECT_TRUE(flags.empty());
  set_fold_flag(flags, 5, true);
  EXPECT_TRUE(fold_flag(flags, 5));
  EXPECT_FALSE(fold_flag(flags, 4));
  set_fold_flag(flags, -3, true);
  EXPECT_EQ(flags.size(), 6u);
}

}  // namespace
}  // namespace stanceplan::gui
