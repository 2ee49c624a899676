#pragma once
// Stops a hopeless solve early (opt-in: SolverOptions::stall, scenario key solver.stall_after). A
// candidate stance without a posture rarely ends quickly: Ipopt detects local infeasibility after
// 25-100 iterations or runs to the iteration limit, and such candidates are most of the search's
// solver time (README, "Untuned scenarios"). A solve that progresses keeps its whole budget; one
// whose constraint violation (Ipopt's inf_pr) stalls is stopped:
//   from iteration `after` on, while inf_pr is above `near_feasible`, the best inf_pr of the last
//   `window` iterations must be at least `factor` times smaller than the best one before them.
// A heuristic: a stopped solve is a rejection (never lets anything through), but it can stop one
// that would have succeeded late. Measured over every Ipopt run of the untuned scenarios with the
// rule below: stairs, side-step and walk with a turn, 2 of 100 successes stopped and 65 of 167
// failures (20 % of the iterations saved: bench/untuned_bench 16.3 -> 10.4 s, 5.3 -> 2.3 s,
// same plans); the dual-arm hand-over, 3 of 213 successes stopped and 171 of 409 failures, but a
// stopped success changes the search's route: 558 -> 1058 solver calls, 19 -> 23 steps. Hence
// off by default (after = 0); inf_pr alone does not tell a slow success from a hopeless solve.
//
// A second rule, the progress budget (issue 16: "an iteration budget per candidate that grows only
// for candidates that progress"): a solve gets `budget` iterations; each time its violation falls
// `progress_factor` times below the value that last earned it more (a new decade), or below
// `near_feasible`, it gets `extension` more from there. Simulated offline with 30 / 20 / 10 on the
// Ipopt traces of every solve (per Ipopt run) of the untuned scenarios (lazy expansion) and of the
// paper's (lazy and all at once): it stops none of the 970 runs that succeed, and 114 of the 277
// that fail (saving 41 % of the untuned iterations). On the untuned scenarios expanded all at
// once it stops 20 of 313 successes (the dual-arm hand-over's long plateaus near a violation of
// 1). Ipopt's restoration phase is no better a signal: 64 of those 313 successes pass through it.
// Hence a search option for candidate solves (SearchOptions::progress_budget, carried by the
// request), never a solver default: motion projections and single postures run their course.
#include <cmath>
#include <string>
#include <vector>

namespace stanceplan {

struct StallRule {
  int after = 0;  // iterations every solve gets before the rule applies (0: never stop; 40 tried)
  int window = 30;
  double factor = 1.1;
  double near_feasible = 1e-2;  // a violation below this is converging: never stopped
  // The progress budget: 0 = none (every solve gets max_iterations).
  int budget = 0;
  int extension = 20;
  double progress_factor = 10.0;
};

class StallMonitor {
 public:
  // `max_iterations` sizes the history once (Ipopt may report a few more: they are still kept).
  StallMonitor(const StallRule& rule, int max_iterations);
  // Records inf_pr at `iteration` (Ipopt's count, restoration iterations included); true when the
  // solve should stop (the stall rule or the progress budget).
  bool stalled(int iteration, double violation);
  // What was seen when it stopped, e.g. "constraint violation 0.315 at iteration 30, not 10x below
  // 0.297 (best before iteration 15)".
  const std::string& reason() const { return reason_; }

 private:
  StallRule rule_;
  std::vector<double> prefix_best_;  // prefix_best_[i]: least violation of iterations 0..i
  std::vector<double> history_;      // violation per iteration
  std::string reason_;
  // The progress budget: the last iteration allowed, and the violation that last extended it.
  bool out_of_budget(int iteration, double violation);
  int allowed_ = 0;
  double progress_mark_ = INFINITY;
  int mark_iteration_ = 0;
};

}  // namespace stanceplan
