#include "planner/search/stance_search.h"

#include "planner/search/search_run.h"
#include "planner/search/stance_checks.h"

namespace stanceplan {

const char* to_string(PlanStatus status) {
  switch (status) {
    case PlanStatus::Found: return "found";
    case PlanStatus::Exhausted: return "exhausted";
    case PlanStatus::NodeBudget: return "node budget";
    case PlanStatus::TimeBudget: return "time budget";
    case PlanStatus::Cancelled: return "cancelled";
    case PlanStatus::InitialInfeasible: return "initial stance infeasible";
  }
  return "?";
}

StanceSearch::StanceSearch(const Problem& problem, SearchOptions options)
    : problem_(problem), options_(options) {
  check_pinned_stances(problem);  // before any search: an input error, not a failed search
}

bool StanceSearch::publish(SearchEvent event) {
  if (gate_ && !gate_->pass()) cancelled_ = true;
  if (stopped()) return false;
  event.number = next_event_++;
  if (observer_) observer_(event);
  return true;
}

SearchResult StanceSearch::run() {
  Run run(*this);
  return run.run();
}

}  // namespace stanceplan
