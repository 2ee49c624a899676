#pragma once
// What one plan costs, counted from the search's events (bench/untuned_bench.cpp): every solver
// call with its candidate, status, Ipopt iterations and time, and the figures of the whole plan.
// The counts (calls, iterations, steps) are deterministic for a search that ends by itself (found
// or exhausted); one stopped by its time budget ends wherever the clock stopped it.
#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "planner/scene/scene.h"
#include "planner/search/search_events.h"
#include "planner/search/stance_search.h"

namespace stanceplan::bench {

struct SolverCall {
  std::string change;  // "add robot/l_knee on env/floor", "remove ...", or "initial" (the root)
  PostureStatus status = PostureStatus::Solved;
  bool accepted = false;  // a new node; a solved call that is not one found it in the tree already
  int iterations = 0;
  double time_ms = 0.0;
};

// Every solver call of a search, from its candidate events: the search publishes exactly one per
// call (the root's included), with the call's own iterations and time.
class CallLog {
 public:
  explicit CallLog(const Scene& scene) : scene_(scene) {}
  // The search's observer; it runs on the search's thread only, so the log needs no lock.
  SearchObserver observer() {
    return [this](const SearchEvent& e) {
      if (e.kind == SearchEventKind::Candidate) calls_.push_back(call_of(e));
    };
  }
  const std::vector<SolverCall>& calls() const { return calls_; }

 private:
  SolverCall call_of(const SearchEvent& e) const {
    return {change_of(e), e.status, e.accepted, e.iterations, e.time_ms};
  }
  std::string change_of(const SearchEvent& e) const {
    if (e.candidate_case == CandidateCase::None) return "initial";
    const std::string verb = e.candidate_case == CandidateCase::Add ? "add " : "remove ";
    return verb + scene_.surfaces.id(scene_.system, e.changed.s1) + " on " +
           scene_.surfaces.id(scene_.system, e.changed.s2);
  }

  const Scene& scene_;
  std::vector<SolverCall> calls_;
};

// Nearest-rank percentile (p in (0, 1]) of integers: always one of the values, so that two runs
// with the same calls print the same figure.
inline int percentile(std::vector<int> values, double p) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<size_t>(std::ceil(p * double(values.size())));
  return values[std::clamp<size_t>(rank, 1, values.size()) - 1];
}

struct PlanFigures {
  PlanStatus status = PlanStatus::Exhausted;
  int steps = 0;               // plan steps, the initial one included (0 without a plan)
  int nodes = 0;               // expanded
  int calls = 0;               // solver calls, the root's included
  int milestone_targeted = 0;  // 1-based: the last one targeted (M when the plan is found)
  int milestones = 0;
  int iterations_median = 0;
  int iterations_p95 = 0;
  int rejected = 0;    // calls whose solve failed (not Solved)
  int duplicates = 0;  // solved, but the stance was in the tree already
  double rejected_time_s = 0.0;
  double solver_time_s = 0.0;  // summed over calls (above the wall time with parallel solves)
  double wall_time_s = 0.0;

  bool found() const { return status == PlanStatus::Found; }
  double calls_per_step() const { return steps > 0 ? double(calls) / steps : 0.0; }
  double ms_per_step() const { return steps > 0 ? 1000.0 * wall_time_s / steps : 0.0; }
  double rejected_time_share() const {
    return solver_time_s > 0.0 ? rejected_time_s / solver_time_s : 0.0;
  }
  // The figures that must not change with the thread count or from run to run.
  auto deterministic() const {
    return std::make_tuple(status, steps, nodes, calls, iterations_median, iterations_p95, rejected,
                           duplicates);
  }
};

inline void add_call_figures(PlanFigures& f, const std::vector<SolverCall>& calls) {
  std::vector<int> iterations;
  for (const SolverCall& c : calls) {
    iterations.push_back(c.iterations);
    f.solver_time_s += c.time_ms / 1000.0;
    if (c.status != PostureStatus::Solved) {
      ++f.rejected;
      f.rejected_time_s += c.time_ms / 1000.0;
    } else if (!c.accepted) {
      ++f.duplicates;
    }
  }
  f.iterations_median = percentile(iterations, 0.5);
  f.iterations_p95 = percentile(iterations, 0.95);
}

// What the search's result says of itself, apart from the calls (all a child process has to pass
// back: bench/untuned_bench.cpp plans in one).
struct SearchOutcome {
  PlanStatus status = PlanStatus::Exhausted;
  int steps = 0;  // plan steps, the initial one included (0 without a plan)
  int nodes = 0;
  int calls = 0;
  int milestone = 0;  // SearchResult::milestone, 0-based
  double wall_time_s = 0.0;
};

inline SearchOutcome outcome_of(const SearchResult& result) {
  const bool found = result.status == PlanStatus::Found;
  return {result.status,         found ? int(result.plan.steps.size()) : 0,
          result.nodes_expanded, result.solver_calls,
          result.milestone,      result.wall_time_s};
}

inline PlanFigures figures_of(const SearchOutcome& outcome, const std::vector<SolverCall>& calls,
                              int milestones) {
  PlanFigures f;
  f.status = outcome.status;
  f.steps = outcome.steps;
  f.nodes = outcome.nodes;
  f.calls = outcome.calls;
  f.milestone_targeted = outcome.milestone + 1;
  f.milestones = milestones;
  f.wall_time_s = outcome.wall_time_s;
  add_call_figures(f, calls);
  return f;
}

}  // namespace stanceplan::bench
