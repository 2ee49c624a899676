#pragma once
// Search events made by hand, for tests of what the panel builds from the event stream (the
// tree, its rows, the plots) without running a search.
#include "planner/search/search_events.h"

namespace stanceplan::test {

// A candidate solve from node `parent`; accepted, it made node `node`.
inline SearchEvent candidate(int parent, int node, bool accepted) {
  SearchEvent e;
  e.kind = SearchEventKind::Candidate;
  e.parent = parent;
  e.node = accepted ? node : -1;
  e.accepted = accepted;
  e.status = accepted ? PostureStatus::Solved : PostureStatus::Infeasible;
  return e;
}

// An expansion, milestone, goal or failure event about `node`.
inline SearchEvent of_kind(SearchEventKind kind, int node, int milestone = 0) {
  SearchEvent e;
  e.kind = kind;
  e.node = node;
  e.milestone = milestone;
  return e;
}

}  // namespace stanceplan::test
