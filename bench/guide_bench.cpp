// The computed guide (planner/guide/, docs/METHOD.md section 3, "The guide computed"), per
// scenario of scenarios/guide_free/: the guide's time (goal posture and path), and the whole plan's
// time and solver calls with the guide computed vs the hand-written guide of the file it copies.
// Targets (issue 17): guide <= 1 s per scenario; a guide-free plan within 2x of the hand-guided
// plan's time. One solver process, so that the calls are deterministic. Run (minutes: the plans
// that find nothing run into their budgets):
//   nice -n 10 build/bench/guide_bench --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true --benchmark_filter=guide/   (one command line)
//   nice -n 10 build/bench/guide_bench --benchmark_filter=plan/
#include <benchmark/benchmark.h>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "planner/guide/guide_planner.h"
#include "planner/io/scenario.h"
#include "planner/io/scenario_guide.h"
#include "planner/search/stance_search.h"

namespace stanceplan {
namespace {

// (guide-free copy, the hand-guided file it copies), relative to scenarios/.
const std::vector<std::pair<std::string, std::string>> kPairs = {
    {"walk", "humanoid_walk.yaml"},
    {"walk_turn", "untuned/walk_turn.yaml"},
    {"side_step", "untuned/side_step.yaml"},
    {"stairs", "untuned/stairs.yaml"},
    {"dual_arm", "untuned/dual_arm_handover.yaml"},
    {"table", "two_humanoids_table.yaml"},
    {"desk", "humanoid_sit_desk.yaml"},
    {"ball", "hand_ball_rotate.yaml"},
    {"pen", "hand_pen_regrasp.yaml"},
    {"climb", "humanoid_climb_on_robot.yaml"},
};

std::string scenario_path(const std::string& relative) {
  return std::string(STANCEPLAN_SOURCE_DIR) + "/scenarios/" + relative;
}

void guide_time(benchmark::State& state, const std::string& name) {
  const Scenario s = load_scenario(scenario_path("guide_free/" + name + ".yaml"));
  ComputedGuide guide;
  for (auto _ : state) guide = compute_guide(s, s.guide);
  state.counters["computed"] = guide.status == GuideStatus::Computed;
  state.counters["milestones"] = double(guide.milestones.size());
  state.counters["posture_s"] = guide.posture_time_s;
  state.counters["path_s"] = guide.path_time_s;
  // The path planner's validity checks over its legs: its effort, the same on any machine.
  double checks = 0.0;
  for (const std::int64_t c : guide.leg_checks) checks += double(c);
  state.counters["path_checks"] = checks;
  state.counters["hand_over"] = guide.hand_over_milestone;
  state.counters["stages"] = guide.stages;
}

// The whole plan: the guide as `plan` gives it (computed for a guide-free file, a written one
// completed where partial) and the search, one solver process.
void plan_time(benchmark::State& state, const std::string& file) {
  for (auto _ : state) {
    Scenario s = load_scenario(scenario_path(file));
    const std::optional<ComputedGuide> guide = complete_scenario_guide(s);
    const double guide_s = guide ? guide->time_s : 0.0;
    state.counters["guide_s"] = guide_s;
    if (guide && guide->status != GuideStatus::Computed) {
      state.SkipWithError(guide->message.c_str());
      return;
    }
    SearchOptions options = s.search;
    options.threads = 1;
    const SearchResult r = StanceSearch(s, options).run();
    state.counters["found"] = r.status == PlanStatus::Found;
    state.counters["steps"] = double(r.plan.steps.size());
    state.counters["solver_calls"] = r.solver_calls;
    state.counters["plan_s"] = guide_s + r.wall_time_s;
  }
}

[[maybe_unused]] const bool kRegistered = [] {
  for (const auto& [name, written] : kPairs) {
    benchmark::RegisterBenchmark(("guide/" + name).c_str(), guide_time, name)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("plan/" + name + "/computed").c_str(), plan_time,
                                 "guide_free/" + name + ".yaml")
        ->Unit(benchmark::kSecond)
        ->Iterations(1);
    benchmark::RegisterBenchmark(("plan/" + name + "/written").c_str(), plan_time, written)
        ->Unit(benchmark::kSecond)
        ->Iterations(1);
  }
  return true;
}();

}  // namespace
}  // namespace stanceplan
