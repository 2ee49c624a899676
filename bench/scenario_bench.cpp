// Whole plans of the scenario files, with 1 and 2 threads: wall time per plan, and the plan's
// steps, expanded nodes, solver calls and solver time share as counters (the README's scenario
// table; the target on the 2-core machine is <= 10 s per scenario). One plan takes seconds, so
// each benchmark runs one iteration per repetition. Run:
//   build/bench/scenario_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
// and pick scenarios with --benchmark_filter=sit_desk (names: scenario/threads).
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "bench/scenario_list.h"
#include "bench/solver_switches.h"
#include "planner/io/scenario.h"
#include "planner/search/stance_search.h"

namespace stanceplan {
namespace {

void plan_scenario(benchmark::State& state, const std::string& name) {
  Scenario scenario = load_scenario(bench::scenario_path(name));
  bench::apply_solver_switches(scenario.solver);
  SearchOptions options = scenario.search;
  options.threads = static_cast<int>(state.range(0));
  SearchResult result;
  for (auto _ : state) result = StanceSearch(scenario, options).run();
  if (result.status != PlanStatus::Found) {
    state.SkipWithError(("no plan: " + result.message).c_str());
    return;
  }
  state.counters["steps"] = static_cast<double>(result.plan.steps.size());
  state.counters["nodes"] = result.nodes_expanded;
  state.counters["solver_calls"] = result.solver_calls;
  // Summed solve time over the wall time: above 1 when solves run in parallel.
  state.counters["solver_share"] = result.solver_time_s / result.wall_time_s;
}

bool register_all() {
  for (benchmark::internal::Benchmark* b : bench::register_scenarios(plan_scenario))
    b->ArgName("threads")->Arg(1)->Arg(2);
  return true;
}
const bool registered = register_all();

}  // namespace
}  // namespace stanceplan
