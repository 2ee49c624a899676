#include "app/gui/session_mirror.h"

namespace stanceplan::gui {

size_t SessionMirror::sync(const app::PlanSession& session) {
  // finished() first: once it holds, every event is already stored, so none is missed.
  const bool finished = session.finished();
  const size_t before = events_.size();
  for (size_t i = before, n = session.event_count(); i < n; ++i) {
    events_.push_back(session.event(i));
    tree_.add(events_.back(), i);
  }
  if (finished && !result_) result_ = session.result();
  return events_.size() - before;
}

long SessionMirror::last_of(SearchEventKind kind, size_t count) const {
  for (size_t i = std::min(count, events_.size()); i-- > 0;)
    if (events_[i].kind == kind) return static_cast<long>(i);
  return -1;
}

}  // namespace stanceplan::gui
