#pragma once
// Environment switches that change the search's options in the whole-plan benchmarks, for
// experiments (is lazy expansion better on this set? what does a shorter budget show?):
//   STANCEPLAN_EXPANSION_BATCH=n   SearchOptions::expansion_batch (0: every candidate at once)
//   STANCEPLAN_ORDER_CANDIDATES=0|1  SearchOptions::order_candidates
//   STANCEPLAN_TIME_LIMIT=s        SearchOptions::time_limit_s
//   STANCEPLAN_PROGRESS_BUDGET=n   SearchOptions::progress_budget (0: none)
//   STANCEPLAN_BATCH_MARGIN=m      SearchOptions::batch_margin (negative: no batch of one)
#include <cstdlib>

#include "planner/search/search_options.h"

namespace stanceplan::bench {

inline void apply_search_switches(SearchOptions& o) {
  if (const char* n = std::getenv("STANCEPLAN_EXPANSION_BATCH")) o.expansion_batch = std::atoi(n);
  if (const char* b = std::getenv("STANCEPLAN_ORDER_CANDIDATES"))
    o.order_candidates = std::atoi(b) != 0;
  if (const char* s = std::getenv("STANCEPLAN_TIME_LIMIT")) o.time_limit_s = std::atof(s);
  if (const char* n = std::getenv("STANCEPLAN_PROGRESS_BUDGET")) o.progress_budget = std::atoi(n);
  if (const char* m = std::getenv("STANCEPLAN_BATCH_MARGIN")) o.batch_margin = std::atof(m);
}

}  // namespace stanceplan::bench
