// Success rate of each scenario's plan when the initial guess moves by a centimetre or two: the
// base of every floating entity shifted by one of eight offsets in x or y (1 and 2 cm), the plan
// searched from there (the root solve brings the robots back onto their initial contacts). A plan
// that is found only from the exact guess of the scenario file depends on solver round-off, not on
// the task. Counter `success` is the fraction of the eight that found a plan (1 = robust);
// STANCEPLAN_VERBOSE=1 prints each run's nodes and solver calls. The guide-free copies
// (guide_free/NAME) plan with the guide computed from the shifted start, the untuned files
// (untuned/NAME) with their coarse guides completed from it where `plan` completes them. Run:
//   build/bench/robustness_bench --benchmark_filter=sit_desk
//   build/bench/robustness_bench --benchmark_filter=guide_free/desk
#include <benchmark/benchmark.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <string>
#include <vector>

#include "bench/computed_guide.h"
#include "bench/scenario_list.h"
#include "bench/solver_switches.h"
#include "planner/io/scenario.h"
#include "planner/search/stance_search.h"

namespace stanceplan {
namespace {

constexpr std::array<std::array<double, 2>, 8> kOffsets = {
    {{0.01, 0}, {-0.01, 0}, {0, 0.01}, {0, -0.01}, {0.02, 0}, {-0.02, 0}, {0, 0.02}, {0, -0.02}}};

void plan_perturbed(benchmark::State& state, const std::string& name) {
  const std::string path = bench::scenario_path(name);
  int found = 0, tried = 0, calls = 0;
  for (auto _ : state) {
    for (const auto& offset : kOffsets) {
      Scenario scenario = load_scenario(path);
      bench::apply_solver_switches(scenario.solver);
      const System& system = scenario.scene.system;
      for (int e = 0; e < system.num_entities(); ++e) {
        if (!system.entity(e).floating()) continue;
        scenario.initial_configuration[system.offset(e) + 0] += offset[0];
        scenario.initial_configuration[system.offset(e) + 1] += offset[1];
      }
      // The guide `plan` gives it, computed (or completed) from the shifted start.
      if (!bench::guide_as_plan_gives(scenario)) {
        ++tried;
        continue;
      }
      SearchOptions options = scenario.search;
      options.threads = 1;
      const SearchResult result = StanceSearch(scenario, options).run();
      found += result.status == PlanStatus::Found;
      calls += result.solver_calls;
      if (std::getenv("STANCEPLAN_VERBOSE"))
        std::fprintf(stderr, "%s offset (%g, %g): %s, %d nodes, %d solver calls\n", name.c_str(),
                     offset[0], offset[1],
                     result.status == PlanStatus::Found ? "found" : "not found",
                     result.nodes_expanded, result.solver_calls);
      ++tried;
    }
  }
  state.counters["success"] = tried > 0 ? double(found) / tried : 0.0;
  state.counters["found"] = found;
  state.counters["tried"] = tried;
  state.counters["solver_calls"] = calls;  // over the eight
}

const auto registered = bench::register_scenarios(plan_perturbed);

// Each file of scenarios/FOLDER/ in `names`, one iteration over the eight starts.
bool register_folder(const std::string& folder, std::initializer_list<const char*> names) {
  for (const char* name : names)
    benchmark::RegisterBenchmark((folder + "/" + name).c_str(), plan_perturbed, folder + "/" + name)
        ->Iterations(1)
        ->Unit(benchmark::kSecond)
        ->UseRealTime();
  return true;
}

// The guide-free copies of the paper's scenarios (scenarios/guide_free/), each with the guide
// computed from its shifted start, as `stanceplan plan` computes it; the untuned scenarios
// (scenarios/untuned/), their coarse guides completed from the shifted start where `plan`
// completes them (the desk's posture change).
[[maybe_unused]] const bool kGuideFree = register_folder(
    "guide_free", {"walk", "desk", "ball", "pen", "dual_arm", "table", "climb", "stairs"});
[[maybe_unused]] const bool kUntuned =
    register_folder("untuned", {"stairs", "walk_turn", "side_step", "dual_arm_handover", "desk"});

}  // namespace
}  // namespace stanceplan
