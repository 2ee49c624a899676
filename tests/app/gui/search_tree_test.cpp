// SearchTree: the panel's tree rebuilt from events alone.
#include "app/gui/search_tree.h"

#include <gtest/gtest.h>

#include "tests/support/search_event_fakes.h"

namespace stanceplan::gui {
namespace {

using test::candidate;
using test::of_kind;

// root 0 -> expanded: 1 accepted, one rejected, 2 accepted; 1 expanded -> 3 accepted, reaches
// milestone 1; plan found at 3.
std::vector<SearchEvent> story() {
  return {candidate(-1, 0, true),
          of_kind(SearchEventKind::Expansion, 0),
          candidate(0, 1, true),
          candidate(0, -1, false),
          candidate(0, 2, true),
          of_kind(SearchEventKind::Expansion, 1),
          candidate(1, 3, true),
          of_kind(SearchEventKind::Milestone, 3, 1),
          of_kind(SearchEventKind::PlanFound, 3)};
}

TEST(SearchTree, RebuildsNodesChildrenAndRejectedCandidates) {
  SearchTree tree;
  const auto events = story();
  for (size_t i = 0; i < events.size(); ++i) tree.add(events[i], i);
  ASSERT_EQ(tree.nodes().size(), 4u);
  EXPECT_EQ(tree.node(0)->children, (std::vector<int>{1, 2}));
  EXPECT_EQ(tree.node(0)->rejected, (std::vector<size_t>{3}));
  EXPECT_EQ(tree.node(3)->parent, 1);
  EXPECT_EQ(tree.node(3)->depth, 2);
  EXPECT_EQ(tree.node(3)->event, 6u);
  EXPECT_EQ(tree.node(4), nullptr);
  EXPECT_EQ(tree.node(-1), nullptr);
}

TEST(SearchTree, ColoursNodesByStatus) {
  SearchTree tree;
  const auto events = story();
  for (size_t i = 0; i + 1 < events.size(); ++i) tree.add(events[i], i);  // before the plan
  EXPECT_EQ(tree.status(0), NodeStatus::Expanded);
  EXPECT_EQ(tree.status(2), NodeStatus::Open);
  EXPECT_EQ(tree.status(3), NodeStatus::Milestone);
  EXPECT_TRUE(tree.plan_path().empty());
  tree.add(events.back(), events.size() - 1);
  EXPECT_EQ(tree.goal(), 3);
  EXPECT_EQ(tree.status(3), NodeStatus::Goal);
  EXPECT_EQ(tree.status(1), NodeStatus::PlanPath);
  EXPECT_EQ(tree.status(0), NodeStatus::PlanPath);
  EXPECT_EQ(tree.status(2), NodeStatus::Open);
  EXPECT_EQ(tree.plan_path(), (std::vector<int>{0, 1, 3}));
}

// A transition without a motion (lazy validation): its node and its subtree show it; the plan
// found afterwards goes through the other branch.
TEST(SearchTree, ANodeWithoutMotionAndItsSubtreeAreMarked) {
  SearchTree tree;
  auto events = story();
  events.pop_back();  // the plan through 1 is not found: its transition into 1 has no motion
  events.push_back(of_kind(SearchEventKind::MotionFailed, 1));
  events.push_back(candidate(2, 4, true));
  events.push_back(of_kind(SearchEventKind::PlanFound, 4));
  for (size_t i = 0; i < events.size(); ++i) tree.add(events[i], i);
  EXPECT_EQ(tree.status(1), NodeStatus::NoMotion);
  EXPECT_EQ(tree.status(3), NodeStatus::NoMotion);
  EXPECT_EQ(tree.node(1)->motion_failed, 8);  // the event that dropped it; its subtree's: none
  EXPECT_EQ(tree.node(3)->motion_failed, -1);
  EXPECT_EQ(tree.node(2)->motion_failed, -1);
  EXPECT_EQ(tree.status(4), NodeStatus::Goal);
  EXPECT_EQ(tree.status(2), NodeStatus::PlanPath);
  EXPECT_EQ(tree.plan_path(), (std::vector<int>{0, 2, 4}));
  EXPECT_STREQ(to_string(NodeStatus::NoMotion), "no motion");
}

TEST(SearchTree, AFailureNamesTheClosestNode) {
  SearchTree tree;
  tree.add(candidate(-1, 0, true), 0);
  tree.add(of_kind(SearchEventKind::Failure, 0), 1);
  EXPECT_EQ(tree.closest(), 0);
  EXPECT_EQ(tree.goal(), -1);
}

}  // namespace
}  // namespace stanceplan::gui
