// The motion between steps (planner/motion/) on the plans of the scenario files: each scenario is
// planned once as `plan --motion` plans it (2 threads, its transitions' motion checked by the
// search, which drops those without: not timed), then the motion of the whole plan is computed
// again, one thread, and timed per step. Counters: steps, steps_failed, transitions_dropped (by
// the search), samples, solves and Ipopt iterations per step (both deterministic), and the motion
// time per step, median and p95 (ms; target <= 100 ms on the 2-core machine). Run:
//   build/bench/motion_bench --benchmark_filter=walk
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <vector>

#include "bench/scenario_list.h"
#include "planner/io/scenario.h"
#include "planner/motion/motion_transition_check.h"
#include "planner/motion/plan_motion.h"
#include "planner/search/stance_search.h"
#include "planner/util/heap_tuning.h"

namespace stanceplan {
namespace {

double percentile(std::vector<double> v, double fraction) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[size_t(fraction * double(v.size() - 1) + 0.5)];
}

void plan_motion(benchmark::State& state, const std::string& name) {
  keep_freed_heap_for_solvers();  // as the application does at start-up
  const Scenario scenario = load_scenario(bench::scenario_path(name));
  SearchOptions options = scenario.search;
  options.threads = 2;
  MotionTransitionCheck check(scenario.scene, scenario.solver, MotionOptions{});
  StanceSearch search(scenario, options);
  search.set_transition_check(check.as_check());
  const SearchResult result = search.run();
  if (result.status != PlanStatus::Found) {
    state.SkipWithError(("no plan: " + result.message).c_str());
    return;
  }
  PlanMotionSummary summary;
  double samples = 0.0;
  for (auto _ : state) {
    Plan plan = result.plan;
    summary = add_motion(scenario.scene, scenario.solver, MotionOptions{}, plan);
    samples = 0.0;
    for (const PlanStep& s : plan.steps) samples += s.motion ? s.motion->samples.size() : 0;
  }
  std::vector<double> times;
  double solves = 0.0, iterations = 0.0;
  for (const StepMotionResult& r : summary.steps) {
    times.push_back(r.time_ms);
    solves += r.solves;
    iterations += r.iterations;
  }
  const double steps = std::max<size_t>(summary.steps.size(), 1);
  state.counters["steps"] = double(summary.steps.size());
  state.counters["steps_failed"] = summary.failed_steps;
  state.counters["transitions_dropped"] = result.transitions_dropped;
  state.counters["samples"] = samples;
  state.counters["solves_per_step"] = solves / steps;
  state.counters["iterations_per_step"] = iterations / steps;
  state.counters["median_ms"] = percentile(times, 0.5);
  state.counters["p95_ms"] = percentile(times, 0.95);
}

const bool registered = [] {
  bench::register_scenarios(plan_motion);
  return true;
}();

}  // namespace
}  // namespace stanceplan
