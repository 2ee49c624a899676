#include "planner/solver/stall_monitor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace stanceplan {

StallMonitor::StallMonitor(const StallRule& rule, int max_iterations)
    : rule_(rule), allowed_(rule.budget) {
  if (rule_.after <= 0) return;  // off: no history, nothing allocated
  prefix_best_.reserve(size_t(std::max(0, max_iterations)) + 16);
  history_.reserve(prefix_best_.capacity());
}

bool StallMonitor::stalled(int iteration, double violation) {
  if (rule_.budget > 0 && iteration >= 0 && out_of_budget(iteration, violation)) return true;
  if (rule_.after <= 0 || iteration < 0) return false;
  // Ipopt counts from 0 without gaps; fill a gap (never expected) with the value itself.
  while (int(history_.size()) <= iteration) {
    const double best = prefix_best_.empty() ? violation : std::min(prefix_best_.back(), violation);
    history_.push_back(violation);
    prefix_best_.push_back(best);
  }
  history_[size_t(iteration)] = violation;
  if (iteration < rule_.after || iteration < rule_.window) return false;
  if (!(violation > rule_.near_feasible)) return false;
  const int split = iteration - rule_.window;  // best before: iterations 0..split
  const double before = prefix_best_[size_t(split)];
  double recent = violation;
  for (int i = split + 1; i < iteration; ++i) recent = std::min(recent, history_[size_t(i)]);
  if (recent * rule_.factor <= before || !std::isfinite(recent)) return false;
  char text[160];
  std::snprintf(text, sizeof(text),
                "constraint violation %.3g at iteration %d, best %.3g over the last %d iterations, "
                "not %gx below %.3g (best up to iteration %d)",
                violation, iteration, recent, rule_.window, rule_.factor, before, split);
  reason_ = text;
  return true;
}

// A new decade of the violation (or near feasibility) buys `extension` iterations from here; a
// solve past its allowance stops. The first iterate sets the first mark.
bool StallMonitor::out_of_budget(int iteration, double violation) {
  if (!std::isfinite(progress_mark_)) {
    progress_mark_ = violation;
    mark_iteration_ = iteration;
  } else if (violation * rule_.progress_factor < progress_mark_) {
    progress_mark_ = violation;
    mark_iteration_ = iteration;
    allowed_ = std::max(allowed_, iteration + rule_.extension);
  }
  if (violation < rule_.near_feasible) allowed_ = std::max(allowed_, iteration + rule_.extension);
  if (iteration <= allowed_) return false;
  char text[200];
  std::snprintf(text, sizeof(text),
                "no progress within its iteration budget: constraint violation %.3g at iteration "
                "%d, not %gx below %.3g since iteration %d",
                violation, iteration, rule_.progress_factor, progress_mark_, mark_iteration_);
  reason_ = text;
  return true;
}

}  // namespace stanceplan
