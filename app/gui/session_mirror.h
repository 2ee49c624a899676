#pragma once
// The panel's copy of a running search: every event taken from the PlanSession once, in order,
// and the tree rebuilt from them. The panel draws from this copy only, so drawing never holds the
// session's lock (and never the search).
#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

#include "app/gui/search_tree.h"
#include "app/live/plan_session.h"

namespace stanceplan::gui {

class SessionMirror {
 public:
  // Copies the events published since the last call; returns how many arrived.
  size_t sync(const app::PlanSession& session);

  const std::vector<SearchEvent>& events() const { return events_; }
  const SearchTree& tree() const { return tree_; }
  // The final result, once the session has finished (copied once).
  const std::optional<SearchResult>& result() const { return result_; }
  bool finished() const { return result_.has_value(); }
  // Index of the last event of a kind among the first `count` events, or -1.
  long last_of(SearchEventKind kind, size_t count) const;

 private:
  std::vector<SearchEvent> events_;
  SearchTree tree_;
  std::optional<SearchResult> result_;
};

}  // namespace stanceplan::gui
