#pragma once
// The scenario files the whole-plan benchmarks run, and their registration: a file that does not
// exist (not written yet) is skipped, not an error.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>
#include <vector>

namespace stanceplan::bench {

inline const std::vector<std::string> kScenarios = {
    "humanoid_walk",     "humanoid_sit_desk",   "hand_ball_rotate",       "hand_pen_regrasp",
    "dual_arm_cylinder", "two_humanoids_table", "humanoid_climb_on_robot"};

inline std::string scenario_path(const std::string& name) {
  return std::string(STANCEPLAN_SOURCE_DIR) + "/scenarios/" + name + ".yaml";
}

// Registers `run` once per existing scenario file (one iteration, seconds, wall time); returns the
// registrations so that callers can add arguments.
template <typename Run>
std::vector<benchmark::internal::Benchmark*> register_scenarios(Run run) {
  std::vector<benchmark::internal::Benchmark*> out;
  for (const std::string& name : kScenarios) {
    FILE* f = std::fopen(scenario_path(name).c_str(), "r");
    if (!f) continue;
    std::fclose(f);
    out.push_back(benchmark::RegisterBenchmark(name.c_str(), run, name)
                      ->Iterations(1)
                      ->Unit(benchmark::kSecond)
                      ->UseRealTime());
  }
  return out;
}

}  // namespace stanceplan::bench
