#pragma once
// `stanceplan replay SCENARIO.yaml REQUEST.bin [--print-level N] [--max-iterations N]
// [--progress-budget N] [--show-request]`: solves one candidate's request again, alone, as the
// search solved it (planner/io/request_file.h; the files come from `stanceplan plan --requests
// DIR`): with Ipopt's own iteration log at --print-level 5, another iteration limit or progress
// budget, or what the solver was asked printed first, to see why a candidate was rejected without
// the search around it.
#include <iosfwd>
#include <optional>
#include <string>

namespace stanceplan::app {

struct ReplayOptions {
  std::string scenario;  // the scenario the request was planned for (its scene and solver)
  std::string request;
  int print_level = 0;                // Ipopt's console output (5: per iteration)
  std::optional<int> max_iterations;  // default: the scenario's solver.max_iterations
  // The progress budget (stall_monitor.h) in iterations, 0 for none; default: the request's (the
  // search's search.progress_budget).
  std::optional<int> progress_budget;
  bool show_request = false;  // print the request's contacts (placements, E25 targets) first
};

// 0 solved, 2 not solved (the solver's reason on `out`); InputError on bad input (a file that is
// not a request, or one that does not fit the scenario).
int run_replay(const ReplayOptions& options, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
