#pragma once
// Budgets and tolerances of the stance search (METHOD.md section 3), read from a scenario's
// `search` section and overridable on the command line.
namespace stanceplan {

struct SearchOptions {
  int max_nodes = 2000;              // nodes expanded before giving up
  double time_limit_s = 60.0;        // wall-clock budget
  double milestone_tolerance = 0.15; // distance at which a milestone counts as reached
  int threads = 0;                   // candidate solves in parallel; 0 = the number of cores
};

}  // namespace stanceplan
