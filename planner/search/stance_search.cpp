#include "planner/search/stance_search.h"

#include <algorithm>
#include <thread>

#include "planner/search/search_run.h"
#include "planner/search/stance_checks.h"

namespace stanceplan {

const char* to_string(PlanStatus status) {
  switch (status) {
    case PlanStatus::Found:
      return "found";
    case PlanStatus::Exhausted:
      return "exhausted";
    case PlanStatus::NodeBudget:
      return "node budget";
    case PlanStatus::TimeBudget:
      return "time budget";
    case PlanStatus::Cancelled:
      return "cancelled";
    case PlanStatus::InitialInfeasible:
      return "initial stance infeasible";
  }
  return "?";
}

int solver_processes(const SearchOptions& options) {
  return options.threads > 0 ? options.threads
                             : int(std::max(1u, std::thread::hardware_concurrency()));
}

StanceSearch::StanceSearch(const Problem& problem, SearchOptions options)
    : problem_(problem), options_(options) {
  check_pinned_stances(problem);  // before any search: an input error, not a failed search
}

bool StanceSearch::publish(SearchEvent event) {
  if (gate_) {  // time held here is the observer's, not the search's (time_limit_s)
    const auto start = std::chrono::steady_clock::now();
    if (!gate_->pass()) cancelled_ = true;
    held_ += std::chrono::steady_clock::now() - start;
  }
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
